"""The companion to Fig. 7: every law of the table, its rebound against e.

Called by figures.py (fig12_every_law.png). Reads:
    fig7.csv   `contactlaws restitution mjcf/bouncing_ball.xml --laws all
               --dissipation 0.1 ...`: the simulated first rebound per law and e
    laws.csv   `contactlaws laws --format csv ...`: each law's closed-form
               rebound (empty where the law has none)
The laws come from those files, not from a list here: a row added to the
table (src/laws/law_table.cc) appears by itself. Three columns of small
multiples keep 13 curves readable: the paper's five laws, the laws whose a(e)
stays finite at e = 0 (they cannot rebound below e_post(a(0))), and those whose
a(e) grows like 1/e (they reach e_post -> 0). Top row e_post against e with the
diagonal; bottom row |e_post - e|.
"""

import matplotlib.pyplot as plt
import numpy as np

# A law of the 1/e kind rebounds at most this at e = 0.01 (closed form).
LOW_E, LOW_E_REBOUND = 0.01, 0.05
COLOURS = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple",
           "tab:brown"]
MARKERS = ["o", "^", "s", "v", "D", "P"]


def groups(sim, forms, paper_laws):
    """(title, [law, ...]) per column, in table order."""
    laws = list(dict.fromkeys(sim["law"]))
    paper = [law for law in laws if law in paper_laws]
    inverse, finite = [], []
    for law in laws:
        if law in paper:
            continue
        e, post = forms.get(law, (np.array([]), np.array([])))
        low = np.isclose(e, LOW_E)
        (inverse if low.any() and post[low][0] < LOW_E_REBOUND
         else finite).append(law)
    return [("(a) Flores et al. (2011): the five laws", paper),
            ("(b) a(0) finite; constant c (c v0 = 0.42)", finite),
            ("(c) a(e) ~ 1/e as e -> 0, and exact", inverse)]


def plot_column(ax_e, ax_d, sim, forms, laws, reads_no_e):
    ax_e.plot([0, 1], [0, 1], "k--", lw=0.8)
    for i, law in enumerate(laws):
        style = {"color": COLOURS[i % len(COLOURS)]}
        rows = sim["law"] == law
        e, post = sim["restitution"][rows], sim["restitution_post"][rows]
        # a law that reads no e has no |e_post - e| to speak of
        pairs = [(ax_e, post)] + ([] if law in reads_no_e else [(ax_d, np.abs(post - e))])
        for ax, y in pairs:
            ax.plot(e, y, ls="none", marker=MARKERS[i % len(MARKERS)], ms=3.5,
                    mfc="none", mew=0.9, **style)
        if law in forms:
            fe, fpost = forms[law]
            ax_e.plot(fe, fpost, lw=1, **style)
            ax_d.plot(fe, np.abs(fpost - fe), lw=1, **style)
        ax_e.plot([], [], marker=MARKERS[i % len(MARKERS)], mfc="none",
                  lw=1 if law in forms else 0, label=law, **style)
    ax_e.legend(loc="upper left", fontsize=7.5)
    for ax in (ax_e, ax_d):
        ax.set_xlim(0, 1)
        ax.grid(alpha=0.3)
    ax_e.set_ylim(0, 1.05)
    ax_d.set_ylim(0, None)
    ax_d.set_xlabel("input restitution e")


def fig12_every_law(results, read_csv, closed_forms, paper_laws, save):
    sim = read_csv(results / "fig7.csv",
                   ["law", "restitution", "restitution_post"])
    forms = closed_forms(results)
    family = read_csv(results / "laws.csv", ["law", "family"])
    reads_no_e = set(family["law"][family["family"] == "constant-dissipation"])
    fig, axes = plt.subplots(2, 3, figsize=(14, 8), sharex="col",
                             gridspec_kw={"height_ratios": [3, 2]})
    for col, (title, laws) in enumerate(groups(sim, forms, paper_laws)):
        plot_column(axes[0, col], axes[1, col], sim, forms, laws, reads_no_e)
        axes[0, col].set_title(title, loc="left", fontsize=10)
    axes[0, 0].set_ylabel("$e_{post}$ (first rebound)")
    axes[1, 0].set_ylabel("$|e_{post} - e|$")
    fig.suptitle("Companion to Fig. 7: every law of the table on the paper's "
                 "ball. Markers: simulated (MuJoCo RK4, gravity on, auto "
                 "timestep); lines: closed form (gravity neglected); dashed: "
                 "$e_{post} = e$", fontsize=10)
    fig.tight_layout()
    save(fig, results, "fig12_every_law.png")
