"""Plot the contactlaws comparison of Flores et al. (2011) as PNG figures.

Usage:
    /usr/bin/python3 scripts/figures.py [RESULTS_DIR]     (default: results)

Reads the CSVs that scripts/run.sh makes with the contactlaws CLI and writes,
into RESULTS_DIR:

    fig5_ball_kinematics.png     fig5/trajectories.csv
        paper Fig. 5: ball height and vertical velocity, Flores, e = 0.9
    fig6_first_contact.png       fig6/trajectories.csv, fig6/impacts.csv
        paper Fig. 6: depth, depth rate, force and force-depth loop of the
        first contact, Flores, e = 1.0, 0.8, 0.6, 0.4, 0.2
    fig7_restitution.png         fig7.csv, laws.csv
        paper Fig. 7: post- against pre-impact restitution, five laws, with
        the closed-form rebound of each dissipative law of the hysteresis
        family (laws.csv: `contactlaws laws --format csv`, the program's own
        formulas, not copies of them)
    fig8_table_hertz.png         fig8/trajectories.csv
        paper Fig. 8: ball on the driven table, Hertz
    fig9_table_dissipative.png   fig9/trajectories.csv
        paper Fig. 9: ball on the table, three dissipative laws, e = 0.9, 0.6,
        0.3
    fig10_table_five_laws.png    table-e0.6/trajectories.csv,
                                 table-e0.6/impacts.csv
        no paper counterpart: the five laws on the table at e = 0.6, heights
        over the first 2.5 s and cumulative impact counts over the run
    fig11_energy_ledger.png      fig5/trajectories.csv
        no paper counterpart: energy ledger of the Fig. 5 run
    fig12_every_law.png          fig7.csv, laws.csv
        companion to Fig. 7: every law of the table, e_post and |e_post - e|
        against e (figures_laws.py)

Figs. 8-11 are drawn by figures_runs.py, Fig. 12 by figures_laws.py, with
this module's readers and styles. Prints one line per figure written. If an input is missing it exits with
status 1 and names the file and the command that makes it.
"""

import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

import figures_laws  # noqa: E402
import figures_runs  # noqa: E402

DPI = 150
BALL_RADIUS = 0.1  # m

# Display name and colour of each law, the same in every figure.
LAWS = {
    "hertz": ("Hertz", "black"),
    "kelvin-voigt": ("Kelvin-Voigt", "tab:purple"),
    "hunt-crossley": ("Hunt-Crossley", "tab:blue"),
    "lankarani-nikravesh": ("Lankarani-Nikravesh", "tab:orange"),
    "flores": ("Flores et al.", "tab:red"),
}
MARKERS = {
    "hertz": "s",
    "kelvin-voigt": "D",
    "hunt-crossley": "o",
    "lankarani-nikravesh": "^",
    "flores": "v",
}
# Lankarani-Nikravesh dashed: it nearly coincides with Hunt-Crossley.
LINESTYLES = {"lankarani-nikravesh": "--"}
# The table top is drawn over the ball curves, so it shows where a ball rests.
TABLE_STYLE = {"color": "0.55", "lw": 0.8, "label": "table top", "zorder": 3}

# The commands of scripts/run.sh that make each input; {out} is RESULTS_DIR.
_CL = "build/contactlaws"
_BALL = "mjcf/bouncing_ball.xml"
_TABLE = "mjcf/ball_table.xml"
COMMANDS = {
    "fig5": f"{_CL} compare {_BALL} --laws flores --restitution 0.9"
            " --duration 10 --sample-rate 1000 --timestep auto --accuracy 3e-5"
            " --columns bodies,energy --output-dir {out}/fig5",
    "fig6": f"{_CL} compare {_BALL} --laws flores"
            " --restitution 1.0,0.8,0.6,0.4,0.2 --duration 0.44"
            " --sample-rate 100000 --timestep auto --accuracy 1e-4"
            " --columns pairs --output-dir {out}/fig6",
    "fig7.csv": f"{_CL} restitution {_BALL} --laws all --dissipation 0.1"
                " --restitution 0.05:1.0:0.05 --timestep auto"
                " --output {out}/fig7.csv",
    "laws.csv": f"{_CL} laws --format csv --restitution 0.01:1.0:0.002"
                " > {out}/laws.csv",
    "fig8": f"{_CL} compare {_TABLE} --laws hertz --duration 10"
            " --timestep auto --columns bodies --output-dir {out}/fig8",
    "fig9": f"{_CL} compare {_TABLE}"
            " --laws hunt-crossley,lankarani-nikravesh,flores"
            " --restitution 0.9,0.6,0.3 --duration 10 --timestep auto"
            " --columns bodies --output-dir {out}/fig9",
    "table-e0.6": f"{_CL} compare {_TABLE} --laws {','.join(LAWS)}"
                  " --restitution 0.6 --duration 10 --timestep auto"
                  " --columns bodies --output-dir {out}/table-e0.6",
}
INPUTS = [
    "fig5/trajectories.csv",
    "fig6/trajectories.csv", "fig6/impacts.csv",
    "fig7.csv", "laws.csv",
    "fig8/trajectories.csv",
    "fig9/trajectories.csv",
    "table-e0.6/trajectories.csv", "table-e0.6/impacts.csv",
]
TEXT_COLUMNS = {"law", "pair", "geom1", "geom2", "family"}


# --------------------------------------------------------------------------
# Reading
# --------------------------------------------------------------------------

def check_inputs(results):
    """Exit with status 1 on the first missing input, naming its maker."""
    for name in INPUTS:
        path = results / name
        if not path.is_file():
            command = COMMANDS[name.split("/")[0]].format(out=results)
            sys.exit(f"figures.py: missing {path}; make it (from the "
                     f"repository root) with: {command}"
                     " (or: bash scripts/run.sh)")


def read_csv(path, columns):
    """Read the named columns of a CSV into numpy arrays.

    Text columns (law, pair, geom1, geom2) stay strings; the others become
    floats, with empty fields as NaN.
    """
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        missing = [c for c in columns if c not in header]
        if missing:
            sys.exit(f"figures.py: {path} has no column(s) {missing}")
        index = [header.index(c) for c in columns]
        rows = [[row[i] for i in index] for row in reader]
    values = zip(*rows) if rows else [()] * len(columns)
    table = {}
    for name, col in zip(columns, values):
        if name in TEXT_COLUMNS:
            table[name] = np.array(col, dtype=str)
        else:
            table[name] = np.array([float(v) if v else np.nan for v in col])
    return table


def select(table, law, restitution=None):
    """Rows of one run, told apart by (law, restitution)."""
    mask = table["law"] == law
    if restitution is not None:
        mask &= np.isclose(table["restitution"], restitution)
    if not mask.any():
        sys.exit(f"figures.py: no rows for law {law}, restitution "
                 f"{restitution} in the results")
    return {name: col[mask] for name, col in table.items()}


def read_trajectories(results, name, body_columns=(), contact=None,
                      energy=False):
    """Read law, restitution, time and the wanted trajectory columns."""
    columns = ["law", "restitution", "time", *body_columns]
    if contact:
        columns += [f"{contact}.{q}" for q in ("depth", "depth_rate", "force")]
    if energy:
        columns += [f"energy.{q}" for q in
                    ("kinetic", "potential", "elastic", "dissipated", "total")]
    return read_csv(results / name / "trajectories.csv", columns)


def read_impacts(results, name):
    return read_csv(results / name / "impacts.csv",
                    ["law", "restitution", "index", "time_contact"])


# --------------------------------------------------------------------------
# Helpers
# --------------------------------------------------------------------------

def law_name(law):
    return LAWS[law][0]


def law_colour(law):
    return LAWS[law][1]


def law_line(law, lw=1.1):
    """Line style of a law in the height plots."""
    return {"color": law_colour(law), "ls": LINESTYLES.get(law, "-"),
            "lw": lw}


def save(fig, results, filename):
    path = results / filename
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    print(f"wrote {path}")


def first_contact(run, contact):
    """Slice of the first contact episode, zero-depth boundary rows in."""
    depth = run[f"{contact}.depth"]
    touching = depth > 0
    if not touching.any():
        sys.exit("figures.py: a run of fig6 never touches the floor")
    start = int(np.argmax(touching))
    after = depth[start:] <= 0
    end = start + int(np.argmax(after)) if after.any() else len(depth) - 1
    return slice(max(start - 1, 0), end + 1)


def closed_forms(results):
    """Each dissipative law's closed-form rebound, from the program.

    laws.csv (`contactlaws laws --format csv`) gives, per law and e, the
    hysteresis coefficient a(e) and the rebound e_post that solves
    a (1 + e_post) = ln((1 + a) / (1 - a e_post)); empty where the law has
    no closed form (kelvin-voigt) or e is outside its range. Elastic laws
    (a = 0 everywhere) are left out. Returns {law: (e, e_post)}.
    """
    table = read_csv(results / "laws.csv",
                     ["law", "restitution", "hysteresis_coefficient",
                      "effective_restitution"])
    forms = {}
    for law in dict.fromkeys(table["law"]):
        rows = select(table, law)
        known = ~np.isnan(rows["effective_restitution"])
        if not known.any() or not np.nanmax(rows["hysteresis_coefficient"]) > 0:
            continue
        forms[law] = (rows["restitution"][known],
                      rows["effective_restitution"][known])
    return forms


# --------------------------------------------------------------------------
# Figures
# --------------------------------------------------------------------------

def fig5_ball_kinematics(results):
    traj = read_trajectories(results, "fig5", ["ball.z", "ball.vz"])
    run = select(traj, "flores", 0.9)
    fig, (ax_z, ax_v) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    colour = law_colour("flores")
    ax_z.plot(run["time"], run["ball.z"], color=colour, lw=1,
              label="ball centre")
    ax_z.axhline(BALL_RADIUS, color="0.5", lw=0.8, ls=":",
                 label="touching the floor (z = R = 0.1 m)")
    ax_z.legend(loc="upper right", fontsize=9)
    ax_z.set_ylabel("ball centre height z (m)")
    ax_z.set_title("(a) position", loc="left", fontsize=10)
    ax_v.plot(run["time"], run["ball.vz"], color=colour, lw=1)
    ax_v.axhline(0, color="0.5", lw=0.6)
    ax_v.set_ylabel("vertical velocity $v_z$ (m/s)")
    ax_v.set_xlabel("time (s)")
    ax_v.set_title("(b) velocity", loc="left", fontsize=10)
    for ax in (ax_z, ax_v):
        ax.grid(alpha=0.3)
    ax_v.set_xlim(run["time"][0], run["time"][-1])
    fig.suptitle("Fig. 5 (Flores et al. 2011): bouncing ball, "
                 "Flores et al. law, e = 0.9")
    fig.tight_layout()
    save(fig, results, "fig5_ball_kinematics.png")


def fig6_first_contact(results):
    contact = "ball-floor"
    traj = read_trajectories(results, "fig6", contact=contact)
    impacts = read_impacts(results, "fig6")
    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5))
    (ax_d, ax_r), (ax_f, ax_loop) = axes
    cmap = plt.get_cmap("viridis")
    restitutions = (1.0, 0.8, 0.6, 0.4, 0.2)
    for k, e in enumerate(restitutions):
        run = select(traj, "flores", e)
        first = select(impacts, "flores", e)
        t0 = first["time_contact"][first["index"] == 1][0]
        rows = first_contact(run, contact)
        t_ms = (run["time"][rows] - t0) * 1e3
        depth_mm = run[f"{contact}.depth"][rows] * 1e3
        rate = run[f"{contact}.depth_rate"][rows]
        force_kn = run[f"{contact}.force"][rows] * 1e-3
        style = {"color": cmap(k / len(restitutions)), "lw": 1.3,
                 "label": f"e = {e:.1f}"}
        ax_d.plot(t_ms, depth_mm, **style)
        # out of contact the CLI writes depth rate 0: plot only the rows in
        # contact, or the boundary rows draw false jumps to zero
        inside = depth_mm > 0
        ax_r.plot(t_ms[inside], rate[inside], **style)
        ax_f.plot(t_ms, force_kn, **style)
        ax_loop.plot(depth_mm, force_kn, **style)
    time_label = "time since first touch (ms)"
    panels = [
        (ax_d, "(a) deformation", time_label, "depth (mm)"),
        (ax_r, "(b) rate of deformation (rows in contact only)",
         time_label, "depth rate (m/s, > 0 approaching)"),
        (ax_f, "(c) contact force", time_label, "force (kN)"),
        (ax_loop, "(d) force against deformation", "depth (mm)",
         "force (kN)"),
    ]
    for ax, title, xlabel, ylabel in panels:
        ax.set_title(title, loc="left", fontsize=10)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    ax_r.axhline(0, color="0.5", lw=0.6)
    ax_d.legend(title="Flores et al.", fontsize=9)
    fig.suptitle("Fig. 6 (Flores et al. 2011): first ball-floor contact, "
                 "Flores et al. law\n(time zero = time_contact of the first "
                 "impact in impacts.csv)", fontsize=11)
    fig.tight_layout()
    save(fig, results, "fig6_first_contact.png")


def fig7_restitution(results):
    data = read_csv(results / "fig7.csv",
                    ["law", "restitution", "restitution_post"])
    forms = closed_forms(results)
    fig, ax = plt.subplots(figsize=(10, 6))
    ax.plot([0, 1], [0, 1], "k--", lw=1)
    for law in LAWS:
        run = select(data, law)
        ax.plot(run["restitution"], run["restitution_post"], ls="none",
                marker=MARKERS[law], ms=6, mfc="none", mew=1.3,
                color=law_colour(law))
        if law in forms:
            ax.plot(*forms[law], color=law_colour(law), lw=1)
    law_handles = [
        Line2D([], [], color=law_colour(law), marker=MARKERS[law], mfc="none",
               mew=1.3, lw=1 if law in forms else 0,
               label=law_name(law))
        for law in LAWS
    ]
    key_handles = [
        Line2D([], [], color="0.3", marker="o", mfc="none", ls="none",
               label="markers: simulated\n"
                     "(MuJoCo RK4, gravity on, auto timestep)"),
        Line2D([], [], color="0.3", lw=1,
               label="lines: closed form\n(gravity neglected)"),
        Line2D([], [], color="k", ls="--", lw=1, label="$e_{post} = e$"),
    ]
    # both legends outside the axes: every corner of the square holds data
    law_legend = ax.legend(handles=law_handles, loc="upper left",
                           bbox_to_anchor=(1.02, 1.0), title="law",
                           fontsize=9)
    ax.add_artist(law_legend)
    ax.legend(handles=key_handles, loc="lower left",
              bbox_to_anchor=(1.02, 0.0), fontsize=9)
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1.05)
    ax.set_xlabel("input (pre-impact) restitution e")
    ax.set_ylabel("post-impact restitution $e_{post}$ = "
                  "separation / impact speed")
    ax.set_title("Fig. 7 (Flores et al. 2011): post- against pre-impact "
                 "restitution,\nfirst impact of the bouncing ball",
                 fontsize=11)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, results, "fig7_restitution.png")


FIGURES = [
    fig5_ball_kinematics,
    fig6_first_contact,
    fig7_restitution,
    lambda results: figures_runs.fig8_table_hertz(results, sys.modules[__name__]),
    lambda results: figures_runs.fig9_table_dissipative(results, sys.modules[__name__]),
    lambda results: figures_runs.fig10_table_five_laws(results, sys.modules[__name__]),
    lambda results: figures_runs.fig11_energy_ledger(results, sys.modules[__name__]),
    lambda results: figures_laws.fig12_every_law(
        results, read_csv, closed_forms, LAWS, save),
]


def main(argv):
    if len(argv) > 2:
        sys.exit("usage: figures.py [RESULTS_DIR]")
    results = Path(argv[1] if len(argv) > 1 else "results")
    check_inputs(results)
    for make in FIGURES:
        make(results)


if __name__ == "__main__":
    main(sys.argv)
