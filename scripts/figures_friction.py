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

    friction_chung_ooi_test4.png  chung_ooi/test4_<material>_<angle>.csv
        Chung & Ooi's test 4 (mjcf/chung_ooi_oblique.xml swept over the
        angle): tangential restitution, spin and the contact surface's
        rebound angle, beside the rigid sphere's sliding and rolling
    friction_chung_ooi_test5.png  chung_ooi/test5_<material>_<psi>.csv
        test 5: the normalized rebound angle and spin over the normalized
        incident angle, beside the rigid sphere's

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
    "coulomb": ("tab:blue", "-"),
    "stribeck": ("tab:orange", "--"),
    "lugre": ("tab:green", ":"),
    "regularized": ("tab:red", "-"),
    "mujoco": ("black", "-"),
}
LABELS = {"mujoco": "MuJoCo's own (condim 3)",
          "regularized": "regularized (steps of its lag, 1e-5 or 8e-6 s; a shorter run)"}
# the belt's friction axis: up to past mu_s m g (5.9 N), where LuGre's
# bristles overshoot as the block comes to stick on the belt (6.4 N)
BELT_FORCE_LIMITS = (-1, 8)
# mjcf/chung_ooi_oblique.xml and its sweep in scripts/run.sh: mu, e, radius,
# test 4's speed, each material's Poisson ratio
CO = {"mu": 0.092, "e": 0.98, "R": 2.55e-3, "speed": 3.9,
      "nu": {"alumina": 0.23, "alloy": 0.33}}
CHUNG_OOI = {"alumina": ("tab:blue", "alumina"), "alloy": ("tab:red", "aluminium alloy")}
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
        colour, ls = MODELS[model]
        style = {"color": colour, "ls": ls, "lw": 1.2,
                 "label": LABELS.get(model, model)}
        axes[0].plot(t, 100 * run["block.x"], **style)
        axes[1].plot(t, run["block.vx"], **style)
        force = run["block-belt.friction_x"]
        axes[2].plot(t, force, **style)
        if model == "lugre" and force.max() > BELT_FORCE_LIMITS[1]:
            axes[2].annotate(
                f"lugre: {force.max():.0f} N at the start (bristle damping "
                "s1 z' as the belt starts under the block)",
                xy=(t[force.argmax()], BELT_FORCE_LIMITS[1]),
                xytext=(0.1, 0.8 * BELT_FORCE_LIMITS[1]), fontsize=7.5,
                color=colour, arrowprops={"arrowstyle": "->",
                                          "color": colour})
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
        axes[2].text(1.0, mu * m * G, f"{name}  ", va="bottom", ha="right",
                     fontsize=8, color="grey",
                     transform=axes[2].get_yaxis_transform())
    axes[2].set_ylim(*BELT_FORCE_LIMITS)
    axes[2].set_ylabel("friction on the block (N)")
    axes[3].set_ylabel("slip on the belt while\ncarried (mm/s)")
    axes[3].set_xlabel("time (s)")
    axes[3].set_title(
        "belt - block while within 2 mm/s of the belt. coulomb, stribeck: "
        "the stick spring stretching as the load grows\n(k v_b / k_t), "
        "not creep; regularized: slip carries the load (transition "
        "velocity 1e-4 m/s); lugre: the bristles", fontsize=8)
    axes[3].set_ylim(-0.3, 0.5)
    axes[1].legend(loc="lower left", fontsize=8)
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
            ls="--", label="w R (spin x radius)")
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
    fig, (ax_v, ax_x) = plt.subplots(1, 2, figsize=(11, 4.8))
    for model, (colour, ls) in MODELS.items():
        run = read(results / "friction" / f"incline_{model}.csv",
                   ["block.x", "block.vx"])
        t, x, v = run["time"][1:], run["block.x"][1:], run["block.vx"][1:]
        style = {"color": colour, "ls": ls, "lw": 1.5,
                 "label": LABELS.get(model, model)}
        ax_v.plot(t, np.maximum(np.abs(v), FLOOR), **style)
        if model in CREEPERS:
            ax_v.text(t[-1], abs(v[-1]), f"{abs(v[-1]):.2g} m/s",
                      va="bottom", ha="right", fontsize=8, color=colour)
        late = t > SINCE
        x0 = np.interp(SINCE, t, x)
        ax_x.plot(t[late], np.maximum(np.abs(x[late] - x0), FLOOR), **style)
    ax_v.set_title("speed down the slope", fontsize=10)
    ax_v.set_ylabel("|v| (m/s)")
    ax_v.text(0.5, 3e-12,
              "coulomb, stribeck, lugre: the block\nsettling (e-fold 0.1 s) and held:\n"
              "< 1e-9 m in 10 s after it\n(docs/friction.md)", fontsize=8)
    ax_x.set_title(f"displacement down the slope since t = {SINCE} s",
                   fontsize=10)
    ax_x.set_ylabel(f"|x(t) - x({SINCE} s)| (m)")
    ax_x.text(0.5, 1e-8, "coulomb, stribeck, lugre: the rest of the\n"
              "settling, then still", fontsize=8)
    for ax in (ax_v, ax_x):
        ax.set_yscale("log")
        ax.set_ylim(FLOOR / 2, 1e-1)
        ax.set_xlabel("time (s)")
        ax.grid(alpha=0.3, which="both")
        ax.axhline(FLOOR, color="grey", lw=0.6)
        ax.text(1.0, FLOOR, f"{FLOOR:g}: zero to rounding ", ha="right",
                va="bottom", fontsize=7, color="grey",
                transform=ax.get_yaxis_transform())
    ax_v.legend(loc="lower left", fontsize=8)
    fig.suptitle("A block on an incline, tan(theta) = 0.3 < mu_s = 0.5: who "
                 "creeps (mjcf/friction_incline.xml, 1e-4 s, RK4)",
                 fontsize=10)
    fig.tight_layout()
    save(fig, results / "friction_incline.png")


# the incline's models that creep, their speed written at the end
CREEPERS = ("regularized", "mujoco")
# the displacement panel starts here, s: the settling mostly done
SINCE = 0.3


def rigid_sliding(tangent, e, mu):
    """The rigid sphere's rebound off a plane, per unit normal speed: v_t',
    w' R and the contact surface's slip after, for an incident tangent
    v_t / v_n. It slides throughout while tangent >= 7/2 mu (1 + e), else it
    leaves rolling at 5/7 v_t."""
    slides = tangent >= 3.5 * mu * (1 + e)
    vt = np.where(slides, tangent - mu * (1 + e), 5 / 7 * tangent)
    spin = np.where(slides, 2.5 * mu * (1 + e), 5 / 7 * tangent)
    return vt, spin, vt - spin


def chung_ooi_runs(results, test, keys):
    """The rebound of each run of one of Chung & Ooi's tests: per material,
    the incident (v_t, v_n) and the final v_t, v_n and spin, by key."""
    out = {}
    for material in CHUNG_OOI:
        rows = []
        for key in keys:
            run = read(results / "friction" / "chung_ooi" / f"{test}_{material}_{key}.csv",
                       ["sphere.vx", "sphere.vz", "sphere.wy"])
            rows.append([run["sphere.vx"][0], -run["sphere.vz"][0], run["sphere.vx"][-1],
                         run["sphere.vz"][-1], run["sphere.wy"][-1]])
        out[material] = np.array(rows).T
    return out


def chung_ooi(results):
    """Chung & Ooi's tests 4 and 5, beside rigid-body sliding."""
    mu, e, radius = CO["mu"], CO["e"], CO["R"]
    angles = np.arange(5, 90, 10)
    runs = chung_ooi_runs(results, "test4", angles)
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    theta = np.linspace(1, 89, 400)
    tangent = np.tan(np.radians(theta))
    vt, spin, slip = rigid_sliding(tangent, e, mu)
    vn = CO["speed"] * np.cos(np.radians(theta))
    axes[0].plot(theta, vt / tangent, color="grey", ls="--", label="rigid body")
    axes[1].plot(theta, spin * vn / radius, color="grey", ls="--", label="rigid body")
    axes[2].plot(theta, np.degrees(np.arctan(slip / e)), color="grey", ls="--",
                 label="rigid body")
    for material, (colour, name) in CHUNG_OOI.items():
        vt0, vn0, vt1, vn1, w1 = runs[material]
        style = dict(color=colour, marker="o", ms=4, lw=1.2, label=name)
        axes[0].plot(angles, vt1 / vt0, **style)
        axes[1].plot(angles, w1, **style)
        axes[2].plot(angles, np.degrees(np.arctan((vt1 - w1 * radius) / vn1)), **style)
    titles = ["tangential restitution v_t' / v_t", "spin after (rad/s)",
              "contact surface's rebound angle (degrees)"]
    for ax, title in zip(axes, titles):
        ax.set_xlabel("incident angle from the normal (degrees)")
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"Chung & Ooi test 4: a 2.55 mm sphere at {CO['speed']} m/s onto a rigid "
                 f"plane, mu {mu}, e {e} (mjcf/chung_ooi_oblique.xml, Mindlin's no-slip spring)",
                 fontsize=10)
    fig.tight_layout()
    save(fig, results / "friction_chung_ooi_test4.png")

    psis = ["0.5", "1", "1.5", "2", "3", "4", "6", "8", "10"]
    runs = chung_ooi_runs(results, "test5", psis)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4))
    for material, (colour, name) in CHUNG_OOI.items():
        nu = CO["nu"][material]
        kappa = 2 * (1 - nu) / (mu * (2 - nu))
        vt0, vn0, vt1, vn1, w1 = runs[material]
        psi = np.linspace(0.01, 10.5, 400)
        vt, spin, slip = rigid_sliding(psi / kappa, e, mu)
        axes[0].plot(psi, kappa * slip / e, color=colour, ls="--", lw=1,
                     label=f"rigid body ({name})")
        axes[1].plot(psi, spin / (psi / kappa), color=colour, ls="--", lw=1,
                     label=f"rigid body ({name})")
        style = dict(color=colour, marker="o", ms=4, lw=1.2, label=name)
        axes[0].plot(kappa * vt0 / vn0, kappa * (vt1 - w1 * radius) / vn1, **style)
        axes[1].plot(kappa * vt0 / vn0, w1 * radius / vt0, **style)
    axes[0].set_title("normalized rebound angle of the contact surface, Psi_2", fontsize=10)
    axes[1].set_title("spin after, w' R / v_t", fontsize=10)
    for ax in axes:
        ax.set_xlabel("normalized incident angle Psi_1 = 2 (1 - nu) / (mu (2 - nu)) v_t / v_n")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"Chung & Ooi test 5: v_n = 5 m/s, v_t varied, mu {mu}, e {e} "
                 "(mjcf/chung_ooi_oblique.xml swept by scripts/run.sh)", fontsize=10)
    fig.tight_layout()
    save(fig, results / "friction_chung_ooi_test5.png")


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
    chung_ooi(results)


if __name__ == "__main__":
    main(sys.argv)
