"""The whole-run figures of scripts/figures.py: the driven table (Figs. 8, 9
and 10) and the energy ledger of Fig. 5's run (Fig. 11).

Called by figures.py, which passes itself as h: its readers (read_trajectories,
read_impacts, select), the laws' names and line styles, save.
"""

import matplotlib.pyplot as plt
import numpy as np


def plot_ball_and_table(ax, runs, table_run, h):
    """Ball lowest point of each run and the table top against time."""
    ax.plot(table_run["time"], table_run["table.z"], **h.TABLE_STYLE)
    for label, run, style in runs:
        ax.plot(run["time"], run["ball.z"] - h.BALL_RADIUS, label=label, **style)
    ax.set_ylabel("height (m)")
    ax.grid(alpha=0.3)



def fig8_table_hertz(results, h):
    traj = h.read_trajectories(results, "fig8", ["ball.z", "table.z"])
    run = h.select(traj, "hertz")
    fig, ax = plt.subplots(figsize=(8, 4.5))
    plot_ball_and_table(
        ax, [("ball lowest point (Hertz)", run, h.law_line("hertz", lw=1))], run, h)
    ax.set_xlabel("time (s)")
    ax.set_xlim(run["time"][0], run["time"][-1])
    ax.legend(loc="upper left", fontsize=9)
    ax.set_title("Fig. 8 (Flores et al. 2011): ball on the driven table "
                 "(top at 0.5 + 0.1 sin 7.5t m), Hertz", fontsize=11)
    fig.tight_layout()
    h.save(fig, results, "fig8_table_hertz.png")


def fig9_table_dissipative(results, h):
    traj = h.read_trajectories(results, "fig9", ["ball.z", "table.z"])
    laws = ("hunt-crossley", "lankarani-nikravesh", "flores")
    restitutions = (0.9, 0.6, 0.3)
    fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True, sharey=True)
    for ax, letter, e in zip(axes, "abc", restitutions):
        runs = [(h.law_name(law), h.select(traj, law, e), h.law_line(law))
                for law in laws]
        plot_ball_and_table(ax, runs, runs[0][1], h)
        ax.set_title(f"({letter}) e = {e}", loc="left", fontsize=10)
    axes[0].legend(loc="upper right", fontsize=9, ncol=2)
    axes[-1].set_xlabel("time (s)")
    axes[-1].set_xlim(traj["time"].min(), traj["time"].max())
    fig.suptitle("Fig. 9 (Flores et al. 2011): ball on the driven table, "
                 "dissipative laws\n(ball lowest point = centre - 0.1 m)",
                 fontsize=11)
    fig.tight_layout()
    h.save(fig, results, "fig9_table_dissipative.png")


def fig10_table_five_laws(results, h, zoom=2.5):
    """Heights over the first `zoom` seconds, impact counts over the run."""
    traj = h.read_trajectories(results, "table-e0.6", ["ball.z", "table.z"])
    impacts = h.read_impacts(results, "table-e0.6")
    t_end = traj["time"].max()
    fig, (ax_h, ax_n) = plt.subplots(
        2, 1, figsize=(10, 7.5), gridspec_kw={"height_ratios": [3, 2]})
    runs = []
    for law in h.LAWS:
        e = None if law == "hertz" else 0.6
        runs.append((h.law_name(law), h.select(traj, law, e), h.law_line(law)))
        hits = np.sort(h.select(impacts, law, e)["time_contact"])
        times = np.concatenate(([0.0], hits, [t_end]))
        counts = np.concatenate(([0], np.arange(1, len(hits) + 1),
                                 [len(hits)]))
        ax_n.step(times, counts, where="post", lw=1.3,
                  color=h.law_colour(law), ls=h.LINESTYLES.get(law, "-"),
                  label=f"{h.law_name(law)}: {len(hits)}")
    plot_ball_and_table(ax_h, runs, runs[0][1], h)
    ax_h.set_xlim(0, zoom)
    ax_h.set_ylim(0.35, 1.35)
    ax_h.set_xlabel("time (s)")
    ax_h.set_title(f"(a) ball lowest point and table top, first {zoom} s "
                   "(Hertz ignores e)", loc="left", fontsize=10)
    ax_n.set_xlim(0, t_end)
    ax_n.set_xlabel("time (s)")
    ax_n.set_ylabel("impacts")
    ax_n.set_title(f"(b) cumulative number of impacts, whole {t_end:g} s run",
                   loc="left", fontsize=10)
    ax_n.grid(alpha=0.3)
    for ax, title in ((ax_h, None), (ax_n, "impacts in total")):
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=9,
                  title=title, title_fontsize=9)
    fig.suptitle("Fig. 10 (no counterpart in Flores et al. 2011): "
                 "the five laws on the driven table, e = 0.6", fontsize=11)
    fig.tight_layout()
    h.save(fig, results, "fig10_table_five_laws.png")


def fig11_energy_ledger(results, h):
    traj = h.read_trajectories(results, "fig5", energy=True)
    run = h.select(traj, "flores", 0.9)
    time = run["time"]
    fig, (ax_e, ax_err) = plt.subplots(
        2, 1, figsize=(8, 6.5), sharex=True,
        gridspec_kw={"height_ratios": [3, 1]})
    terms = [("kinetic", "tab:blue", 0.9), ("potential", "tab:green", 0.9),
             ("elastic", "tab:purple", 0.9), ("dissipated", "tab:red", 1.3),
             ("total", "black", 2.0)]
    for term, colour, lw in terms:
        ax_e.plot(time, run[f"energy.{term}"], color=colour, lw=lw,
                  label=term)
    ax_e.set_ylabel("energy (J)")
    ax_e.set_title("(a) energy ledger (potential = m g z of the centre)",
                   loc="left", fontsize=10)
    ax_e.legend(loc="center right", fontsize=9)
    drift_mj = (run["energy.total"] - run["energy.total"][0]) * 1e3
    ax_err.plot(time, drift_mj, color="black", lw=1)
    ax_err.axhline(0, color="0.5", lw=0.6)
    ax_err.annotate(f"at the end: {drift_mj[-1]:+.1f} mJ "
                    f"({drift_mj[-1] / run['energy.total'][0] / 10:+.2f} %)",
                    xy=(0.99, 0.93), xycoords="axes fraction", ha="right",
                    va="top", fontsize=9)
    ax_err.set_ylabel("total - total(0)\n(mJ)")
    ax_err.set_xlabel("time (s)")
    ax_err.set_title("(b) drift of the total (spikes: samples taken inside "
                     "a contact)",
                     loc="left", fontsize=10)
    for ax in (ax_e, ax_err):
        ax.grid(alpha=0.3)
    ax_err.set_xlim(time[0], time[-1])
    fig.suptitle("Fig. 11 (no counterpart in Flores et al. 2011): energy "
                 "of the Fig. 5 run, Flores et al. law, e = 0.9", fontsize=11)
    fig.tight_layout()
    h.save(fig, results, "fig11_energy_ledger.png")
