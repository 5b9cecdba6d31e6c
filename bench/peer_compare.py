#!/usr/bin/env python3
"""Peer comparison: contactlaws' Hunt-Crossley bouncing ball against Simbody's
HuntCrossleyForce on the same ball (tools/peer/README.md).

    python3 bench/peer_compare.py --simbody build-peer/simbody_ball
        [--contactlaws build/contactlaws] [--runs N] [--restitution 0.8,0.5]
        [--accuracy 1e-6] [--duration 2]

For each restitution e, runs the two whole processes N times (default 11),
alternating (contactlaws first on odd rounds, Simbody first on even ones):
  contactlaws run mjcf/bouncing_ball.xml --law hunt-crossley --restitution E
      --timestep auto --duration T --impacts FILE      (e_post: first row)
  simbody_ball --restitution E --accuracy TOL --duration T
      (Runge-Kutta-Merson; e_post from its output)
and prints the medians of the wall time (and of the CPU time, user + sys, which
other load on a shared machine disturbs less), the e_post of each and its
error, and the ratio contactlaws / Simbody. Goal (the issue): contactlaws'
|error| <= Simbody's and wall-time ratio <= 0.5.

The error is taken against a reference that keeps gravity during the contact:
the 1-D contact ODE  x'' = g - K x^1.5 (1 + a x'/v0)_+ / m  (x depth, from
x = 0, x' = v0 to x = 0 again) integrated here by classical RK4 at 1e-7 s and
2e-7 s (the two must agree to 1e-9) with the last step cut to land on x = 0.
Also printed: the gravity-free e_post of a (1 + e) = ln((1 + a)/(1 - a e)),
which gravity moves by ~4e-4 (e = 0.8) and ~8e-4 (e = 0.5), far more than
either engine's error, and a Simbody run at accuracy 1e-10 as a cross-check of
the reference. Standard library only.
"""

import argparse
import csv
import math
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

# mjcf/bouncing_ball.xml (tools/peer/simbody_ball.cc uses the same numbers).
MASS = 1.0
RADIUS = 0.1
HEIGHT = 1.0
GRAVITY = 9.81
STIFFNESS = 1.4e8
V0 = math.sqrt(2.0 * GRAVITY * (HEIGHT - RADIUS))
RATIO_GOAL = 0.5
REFERENCE_ACCURACY = 1e-10


def coefficient(e):
    return 1.5 * (1.0 - e)


def exact_no_gravity(e):
    """Root in (0, 1] of a (1 + x) = ln((1 + a)/(1 - a x)) (contactlaws'
    ExactRebound)."""
    a = coefficient(e)
    if a == 0:
        return 1.0
    f = lambda x: a * (1 + x) - math.log((1 + a) / (1 - a * x))
    lo, hi = 1e-12, min(1.0, 1.0 / a - 1e-15)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) > 0:
            lo = mid
        else:
            hi = mid
    return lo


def _accel(x, xd, a, g):
    force = STIFFNESS * x ** 1.5 * (1 + a * xd / V0) if x > 0 else 0.0
    return g - max(force, 0.0) / MASS


def _rk4(x, xd, h, a, g):
    k1x, k1v = xd, _accel(x, xd, a, g)
    k2x, k2v = xd + h / 2 * k1v, _accel(x + h / 2 * k1x, xd + h / 2 * k1v, a, g)
    k3x, k3v = xd + h / 2 * k2v, _accel(x + h / 2 * k2x, xd + h / 2 * k2v, a, g)
    k4x, k4v = xd + h * k3v, _accel(x + h * k3x, xd + h * k3v, a, g)
    return (x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x),
            xd + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v))


def reference_e_post(e, h, g=GRAVITY):
    """e_post of the 1-D contact with gravity, RK4 at step h."""
    a = coefficient(e)
    x, xd = 0.0, V0
    while True:
        x1, xd1 = _rk4(x, xd, h, a, g)
        if x1 <= 0 and xd1 < 0:
            break
        x, xd = x1, xd1
    lo, hi = 0.0, h  # the step that lands on x = 0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if _rk4(x, xd, mid, a, g)[0] > 0:
            lo = mid
        else:
            hi = mid
    return -_rk4(x, xd, lo, a, g)[1] / V0


def timed(cmd):
    """Runs cmd; returns (wall s, cpu s of the child, stdout)."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out, err = proc.communicate()
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        sys.exit(f"peer_compare: {' '.join(cmd)} failed ({proc.returncode}):\n"
                 f"{err.decode()}")
    return wall, out.decode()


def cpu_of_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def contactlaws_run(binary, scene, e, duration, impacts):
    cmd = [binary, "run", scene, "--law", "hunt-crossley", "--restitution", str(e),
           "--timestep", "auto", "--duration", str(duration), "--impacts", impacts]
    cpu0 = cpu_of_children()
    wall, _ = timed(cmd)
    cpu = cpu_of_children() - cpu0
    with open(impacts, newline="") as f:
        first = next(r for r in csv.DictReader(f) if r["index"] == "1")
    return wall, cpu, float(first["restitution_post"])


def simbody_run(binary, e, accuracy, duration):
    cmd = [binary, "--restitution", str(e), "--accuracy", str(accuracy),
           "--duration", str(duration)]
    cpu0 = cpu_of_children()
    wall, out = timed(cmd)
    cpu = cpu_of_children() - cpu0
    values = dict(line.split("=", 1) for line in out.split() if "=" in line)
    return (wall, cpu, float(values["e_post"]), int(values["steps"]),
            float(values["loop_wall_s"]))


def main():
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--contactlaws", default=os.path.join(repo, "build", "contactlaws"))
    p.add_argument("--simbody", default=os.path.join(repo, "build-peer", "simbody_ball"))
    p.add_argument("--scene", default=os.path.join(repo, "mjcf", "bouncing_ball.xml"))
    p.add_argument("--runs", type=int, default=11)
    p.add_argument("--restitution", default="0.8,0.5")
    p.add_argument("--accuracy", type=float, default=1e-6)
    p.add_argument("--duration", type=float, default=2.0)
    args = p.parse_args()
    for b in (args.contactlaws, args.simbody):
        if not os.access(b, os.X_OK):
            sys.exit(f"peer_compare: no executable {b}")
    restitutions = [float(s) for s in args.restitution.split(",")]
    # The force-law mapping, checked against Simbody's own force evaluation.
    for e in restitutions:
        check = subprocess.run([args.simbody, "--check-force", "--restitution", str(e)],
                               capture_output=True, text=True)
        if check.returncode != 0:
            sys.exit(f"peer_compare: Simbody's force differs from K x^1.5 (1 + a x'/v0) "
                     f"at e = {e}:\n{check.stdout}{check.stderr}")
    worst = check.stdout.split()[-1].split("=")[1]

    print(f"contactlaws: {args.contactlaws}")
    print(f"simbody:     {args.simbody} (Runge-Kutta-Merson, accuracy {args.accuracy:g})")
    print(f"scene: {args.scene}, duration {args.duration:g} s, {args.runs} alternating "
          f"runs of each process per e; load average {os.getloadavg()[0]:.2f}")
    print(f"force law: Simbody's HuntCrossleyForce = K x^1.5 (1 + a x'/v0) to {worst} "
          f"relative (simbody_ball --check-force)")
    print()

    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        impacts = os.path.join(tmp, "impacts.csv")
        for e in restitutions:
            ref = reference_e_post(e, 1e-7)
            ref2 = reference_e_post(e, 2e-7)
            if abs(ref - ref2) > 1e-9:
                sys.exit(f"peer_compare: reference not converged at e = {e}")
            sb_tight = simbody_run(args.simbody, e, REFERENCE_ACCURACY,
                                   args.duration)[2]
            cl, sb = [], []
            for i in range(args.runs):
                order = ("cl", "sb") if i % 2 == 0 else ("sb", "cl")
                for who in order:
                    if who == "cl":
                        cl.append(contactlaws_run(args.contactlaws, args.scene, e,
                                                  args.duration, impacts))
                    else:
                        sb.append(simbody_run(args.simbody, e, args.accuracy,
                                              args.duration))
            # Both are deterministic: every run gives the same e_post.
            cl_epost, sb_epost = cl[0][2], sb[0][2]
            if any(r[2] != cl_epost for r in cl) or any(r[2] != sb_epost for r in sb):
                print(f"warning: e_post varies between runs at e = {e}")
            rows.append(dict(
                e=e, ref=ref, free=exact_no_gravity(e), sb_tight=sb_tight,
                cl_wall=statistics.median(r[0] for r in cl),
                sb_wall=statistics.median(r[0] for r in sb),
                cl_cpu=statistics.median(r[1] for r in cl),
                sb_cpu=statistics.median(r[1] for r in sb),
                sb_loop=statistics.median(r[4] for r in sb),
                cl_epost=cl_epost, sb_epost=sb_epost, sb_steps=sb[0][3]))

    print("reference e_post (gravity kept; RK4 1e-7 s), the gravity-free formula, "
          f"Simbody at accuracy {REFERENCE_ACCURACY:g}:")
    for r in rows:
        print(f"  e = {r['e']:.2f}: reference {r['ref']:.10f}   gravity-free "
              f"{r['free']:.10f} (gravity moves it by {r['ref'] - r['free']:+.2e})   "
              f"Simbody {r['sb_tight']:.10f} ({r['sb_tight'] - r['ref']:+.1e})")
    print()
    header = (f"{'e':>4} {'engine':<12} {'e_post':>12} {'error':>10} "
              f"{'wall ms':>8} {'cpu ms':>7}")
    print(header)
    print("-" * len(header))
    verdicts = []
    for r in rows:
        for name, ep, wall, cpu in (("contactlaws", r["cl_epost"], r["cl_wall"], r["cl_cpu"]),
                                    ("simbody", r["sb_epost"], r["sb_wall"], r["sb_cpu"])):
            print(f"{r['e']:>4.2f} {name:<12} {ep:>12.8f} {ep - r['ref']:>+10.2e} "
                  f"{wall * 1e3:>8.2f} {cpu * 1e3:>7.2f}")
        ratio = r["cl_wall"] / r["sb_wall"]
        cpu_ratio = r["cl_cpu"] / r["sb_cpu"] if r["sb_cpu"] > 0 else float("nan")
        acc_ok = abs(r["cl_epost"] - r["ref"]) <= abs(r["sb_epost"] - r["ref"])
        ok = acc_ok and ratio <= RATIO_GOAL
        verdicts.append(ok)
        print(f"{r['e']:>4.2f} contactlaws/simbody: wall {ratio:.2f} (cpu {cpu_ratio:.2f}), "
              f"|error| {abs(r['cl_epost'] - r['ref']) / abs(r['sb_epost'] - r['ref']):.2g}x "
              f"Simbody's ({r['sb_steps']} Simbody steps) -> goal "
              f"{'met' if ok else 'NOT met'}"
              f"{'' if acc_ok else ' (accuracy)'}"
              f"{'' if ratio <= RATIO_GOAL else ' (time)'}")
    print()
    print(f"Simbody's stepping loop alone (its own clock), median: " + ", ".join(
        f"{r['sb_loop'] * 1e3:.2f} ms at e = {r['e']:.2f}" for r in rows))
    print(f"goal (|error| <= Simbody's and wall ratio <= {RATIO_GOAL} at every e): "
          f"{'met' if all(verdicts) else 'not met'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
