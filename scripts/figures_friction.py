"""Friction figures: the belt, sliding to rolling, the creep on an incline.

Usage:
    /usr/bin/python3 scripts/figures_friction.py [RESULTS_DIR]   (default: results)
    /usr/bin/python3 scripts/figures_friction.py --creep T0 T1 FILE...

Reads the trajectories scripts/run.sh makes in RESULTS_DIR/friction/ with
`contactlaws run` and writes, into RESULTS_DIR:

    friction_belt.png        belt_<model>.csv (mjcf/friction_belt.xml)
        the block on the belt, held by its spring: position, velocity and
        friction force against time for coulomb, stribeck, lugre and
        regularized, and the block's slip on the belt while it is carried
    friction_slide_roll.png  slide_roll.csv (mjcf/friction_slide_roll.xml)
        v and w R against time meeting at 5/7 v0 at t = 2 v0 / (7 mu g)
    friction_incline.png     incline_<model>.csv (mjcf/friction_incline.xml;
                             incline_mujoco.csv: friction_incline_mujoco.xml)
        the block on the incline: displacement since settling and speed down
        the slope, log scale, per model and with MuJoCo's own contact

--creep prints, for each trajectory FILE, the block's creep down the slope
between the times T0 and T1: the displacement (m) and the mean speed (m/s).
The closed forms' parameters are the scenes' (mjcf/friction_*.xml).
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from figures import DPI, read_csv  # noqa: E402

G = 9.81  # m/s^2
# mjcf/friction_belt.xml: belt speed, spring, mass, mu_s, mu_k
BELT = {"speed": 0.1, "k": 100.0, "m": 1.0, "mu_s": 0.6, "mu_k": 0.4}
# mjcf/friction_slide_roll.xml: launch speed, mu, radius
ROLL = {"v0": 2.0, "mu": 0.3, "R": 0.1}
# the belt's models and the incline's, in plotting order, with their colours
MODELS = {
    "coulomb": "tab:blue",
    "stribeck": "tab:orange",
    "lugre": "tab:green",
    "regularized": "tab:red",
    "mujoco": "black",
}
LABELS = {"mujoco": "MuJoCo's own (condim 3)"}
# Speeds and displacements below this are rounding: drawn at it (log scale)
FLOOR = 1e-15


def read(path, columns):
    if not path.is_file():
        sys.exit(f"figures_friction.py: missing {path}; make it with: "
                 "bash scripts/run.sh")
    return read_csv(path, ["time", *columns])


def save(fig, path):
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    print(f"wrote {path}")


def belt(results):
    fig, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    speed = BELT["speed"]
    for model in ("coulomb", "stribeck", "lugre", "regularized"):
        run = read(results / "friction" / f"belt_{model}.csv",
                   ["block.x", "block.vx", "block-belt.friction_x"])
        t = run["time"]
        style = {"color": MODELS[model], "lw": 1.1, "label": model}
        axes[0].plot(t, 100 * run["block.x"], **style)
        axes[1].plot(t, run["block.vx"], **style)
        axes[2].plot(t, run["block-belt.friction_x"], **style)
        # the slip while carried (within 2 mm/s of the belt)
        slip = speed - run["block.vx"]
        carried = np.abs(slip) < 2e-3
        axes[3].plot(t, np.where(carried, 1e3 * slip, np.nan), **style)
    m, k = BELT["m"], BELT["k"]
    release = BELT["mu_s"] * m * G / k
    axes[0].axhline(100 * release, color="grey", ls=":", lw=0.9)
    axes[0].text(0.01, 100 * release, "  release stretch mu_s m g / k",
                 va="bottom", fontsize=8, color="grey")
    axes[0].set_ylabel("block x (cm)")
    axes[1].axhline(speed, color="grey", ls=":", lw=0.9)
    axes[1].text(0.01, speed, "  belt speed", va="bottom", fontsize=8,
                 color="grey")
    axes[1].set_ylabel("block velocity (m/s)")
    for mu, name in ((BELT["mu_s"], "mu_s m g"), (BELT["mu_k"], "mu_k m g")):
        axes[2].axhline(mu * m * G, color="grey", ls=":", lw=0.9)
        axes[2].text(0.01, mu * m * G, f"  {name}", va="bottom", fontsize=8,
                     color="grey")
    axes[2].set_ylabel("friction on the block (N)")
    axes[3].set_ylabel("slip while carried,\nbelt - block (mm/s)")
    axes[3].set_xlabel("time (s)")
    axes[3].text(0.01, 0.95,
                 "coulomb, stribeck: the stick spring stretching as the "
                 "spring's load grows (k v_b / k_t), not creep;\n"
                 "regularized: slip carries the load (transition velocity "
                 "1e-4 m/s); lugre: the bristles deflecting",
                 transform=axes[3].transAxes, va="top", fontsize=7.5)
    axes[0].legend(loc="lower right", fontsize=8)
    axes[0].set_title("A block on a belt (0.1 m/s) held by a spring: "
                      "stick-slip (mjcf/friction_belt.xml)")
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, results / "friction_belt.png")


def slide_roll(results):
    run = read(results / "friction" / "slide_roll.csv",
               ["ball.vx", "ball.wy", "energy.kinetic"])
    v0, mu, radius = ROLL["v0"], ROLL["mu"], ROLL["R"]
    t_roll = 2 * v0 / (7 * mu * G)
    fig, (ax, ax_e) = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True,
                                   gridspec_kw={"height_ratios": [2, 1]})
    t = run["time"]
    ax.plot(t, run["ball.vx"], color="tab:blue", lw=1.6, label="v (centre)")
    ax.plot(t, radius * run["ball.wy"], color="tab:orange", lw=1.6,
            label="w R (spin)")
    ax.axhline(5 / 7 * v0, color="grey", ls=":", lw=1)
    ax.text(t[-1], 5 / 7 * v0, f"5/7 v0 = {5 / 7 * v0:.4f} m/s",
            ha="right", va="bottom", fontsize=8)
    for a in (ax, ax_e):
        a.axvline(t_roll, color="grey", ls="--", lw=1)
        a.grid(alpha=0.3)
    ax.text(t_roll, 0.1, f" t = 2 v0 / (7 mu g)\n = {t_roll:.4f} s",
            fontsize=8)
    ax.set_ylabel("m/s")
    ax.legend(loc="center right")
    ax.set_title(f"A ball launched sliding at v0 = {v0} m/s, mu = {mu}: "
                 "it rolls at 5/7 v0\n(mjcf/friction_slide_roll.xml, "
                 "coulomb friction)", fontsize=10)
    ke = run["energy.kinetic"]
    ax_e.plot(t, ke / ke[0], color="tab:green", lw=1.4,
              label="kinetic energy / initial")
    ax_e.axhline(5 / 7, color="grey", ls=":", lw=1)
    ax_e.text(t[-1], 5 / 7, "5/7: friction took 2/7", ha="right",
              va="bottom", fontsize=8)
    ax_e.set_ylim(0.6, 1.02)
    ax_e.set_xlabel("time (s)")
    ax_e.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    save(fig, results / "friction_slide_roll.png")


def incline(results):
    fig, (ax_x, ax_v) = plt.subplots(1, 2, figsize=(11, 4.6))
    for model, colour in MODELS.items():
        run = read(results / "friction" / f"incline_{model}.csv",
                   ["block.x", "block.vx"])
        t, x = run["time"], run["block.x"]
        settled = t >= SETTLED
        label = LABELS.get(model, model)
        drift = np.maximum(np.abs(x[settled] - x[settled][0]), FLOOR)
        ax_x.plot(t[settled], drift, color=colour, lw=1.4, label=label)
        ax_v.plot(t, np.maximum(np.abs(run["block.vx"]), FLOOR),
                  color=colour, lw=1.4, label=label)
    ax_x.set_title(f"displacement down the slope since t = {SETTLED} s",
                   fontsize=10)
    ax_x.set_ylabel("|x(t) - x(0.2 s)| (m)")
    ax_v.set_title("speed down the slope", fontsize=10)
    ax_v.set_ylabel("|v| (m/s)")
    for ax in (ax_x, ax_v):
        ax.set_yscale("log")
        ax.set_ylim(FLOOR / 2, 1e-1)
        ax.set_xlabel("time (s)")
        ax.grid(alpha=0.3, which="both")
        ax.axhline(FLOOR, color="grey", lw=0.6)
        ax.text(ax.get_xlim()[1], FLOOR, f"{FLOOR:g}: zero to rounding ",
                ha="right", va="bottom", fontsize=7, color="grey")
    ax_v.legend(loc="center right", fontsize=8)
    fig.suptitle("A block on an incline, tan(theta) = 0.3 < mu_s = 0.5: who "
                 "creeps (mjcf/friction_incline.xml; regularized at "
                 "1e-5 s, the rest at 1e-4 s)", fontsize=10)
    fig.tight_layout()
    save(fig, results / "friction_incline.png")


# The incline runs start at the block's static depth: settled after this, s
SETTLED = 0.2


def creep(t0, t1, paths):
    """Print the creep between t0 and t1 of each trajectory."""
    print("file,displacement_m,speed_m_per_s")
    for path in paths:
        run = read(Path(path), ["block.x"])
        x0 = np.interp(t0, run["time"], run["block.x"])
        x1 = np.interp(t1, run["time"], run["block.x"])
        print(f"{path},{x1 - x0:.3e},{(x1 - x0) / (t1 - t0):.3e}")


def main(argv):
    if len(argv) > 1 and argv[1] == "--creep":
        if len(argv) < 5:
            sys.exit("usage: figures_friction.py --creep T0 T1 FILE...")
        creep(float(argv[2]), float(argv[3]), argv[4:])
        return
    if len(argv) > 2:
        sys.exit("usage: figures_friction.py [RESULTS_DIR]")
    results = Path(argv[1] if len(argv) > 1 else "results")
    belt(results)
    slide_roll(results)
    incline(results)


if __name__ == "__main__":
    main(sys.argv)
