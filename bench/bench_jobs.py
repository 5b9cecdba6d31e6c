#!/usr/bin/env python3
"""The command line's wall times as ratios: --jobs 2 against --jobs 1, and the
paper's whole restitution sweep with --timestep auto against the fixed 1e-5 s.

    python3 bench/bench_jobs.py CONTACTLAWS_BINARY [--repeat N] [--sweep-only]

1. Runs `restitution` and `compare` on mjcf/bouncing_ball.xml with --jobs 1
   and --jobs 2, alternating, N times each (default 3), and prints the median
   wall times and their ratio (target: <= 0.65 on 2 cores). Fails
   (exit 1) when the two write different bytes.
2. Runs `restitution --laws all --dissipation 0.1 --restitution 0.1:1.0:0.1
   --jobs 1` with the scene's 1e-5 s and with --timestep auto (default
   accuracy), alternating, --sweep-repeat times each (default 1), and prints
   the ratio of the median wall times (target: <= 0.02) and the
   largest e_post difference (goal: 2e-3, Kelvin-Voigt 5e-3).
--sweep-only runs part 2 alone.
Wall time, not CPU time: elapsed time is what a user waits for. Standard
library only.
"""

import argparse
import csv
import filecmp
import os
import statistics
import subprocess
import sys
import tempfile
import time

GOAL = 0.65
AUTO_GOAL = 0.02
SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "mjcf", "bouncing_ball.xml")


def commands(out):
    """name -> (arguments without --jobs, the files it writes)."""
    return {
        "restitution --laws all --restitution 0.2:1.0:0.2 (65 runs, fixed 1e-5 s)": (
            ["restitution", SCENE, "--laws", "all", "--dissipation", "0.1", "--restitution", "0.2:1.0:0.2",
             "--quiet", "--output", os.path.join(out, "e.csv")],
            ["e.csv"]),
        "compare --laws all --restitution 0.3,0.6,0.9 --duration 1 (35 runs)": (
            ["compare", SCENE, "--laws", "all", "--dissipation", "0.1", "--restitution", "0.3,0.6,0.9", "--duration",
             "1", "--quiet", "--output-dir", out],
            ["trajectories.csv", "impacts.csv", "summary.csv"]),
    }


def jobs_ratios(binary, repeat, scratch):
    """Part 1: --jobs 2 against --jobs 1; False when the outputs differ."""
    print(f"--jobs 2 / --jobs 1, wall time, median of {repeat} (goal <= {GOAL}); "
          f"{os.cpu_count()} cores")
    same_everywhere = True
    dirs = {jobs: os.path.join(scratch, f"jobs{jobs}") for jobs in (1, 2)}
    for d in dirs.values():
        os.makedirs(d)
    for name in commands(scratch):
        times = {1: [], 2: []}
        for _ in range(repeat):
            for jobs in (1, 2):
                arguments, _ = commands(dirs[jobs])[name]
                start = time.perf_counter()
                subprocess.run([binary, *arguments, "--jobs", str(jobs)], check=True,
                               stdout=subprocess.DEVNULL)
                times[jobs].append(time.perf_counter() - start)
        _, files = commands(scratch)[name]
        same = all(filecmp.cmp(os.path.join(dirs[1], f), os.path.join(dirs[2], f),
                               shallow=False) for f in files)
        one, two = statistics.median(times[1]), statistics.median(times[2])
        ratio = two / one
        verdict = "ok" if ratio <= GOAL else "ABOVE GOAL"
        print(f"  {name}: {one:.2f} s -> {two:.2f} s, ratio {ratio:.3f} ({verdict}); "
              f"output {'identical' if same else 'DIFFERENT'}")
        same_everywhere = same_everywhere and same
    return same_everywhere


def sweep_ratio(binary, repeat, scratch):
    """Part 2: the paper's sweep, fixed 1e-5 s against auto, alternating."""
    times = {"1e-5": [], "auto": []}
    sweeps = {}
    for _ in range(repeat):
        for timestep in times:
            out = os.path.join(scratch, f"sweep-{timestep}.csv")
            start = time.perf_counter()
            subprocess.run([binary, "restitution", SCENE, "--laws", "all", "--dissipation", "0.1",
                            "--restitution", "0.1:1.0:0.1", "--jobs", "1", "--quiet",
                            "--timestep", timestep, "--output", out], check=True,
                           stdout=subprocess.DEVNULL)
            times[timestep].append(time.perf_counter() - start)
            sweeps[timestep] = read_sweep(out)
    fixed, auto = sweeps["1e-5"], sweeps["auto"]
    worst = {}
    for key, e_post in fixed.items():
        kind = "kelvin-voigt" if key[0] == "kelvin-voigt" else "hertz family"
        worst[kind] = max(worst.get(kind, 0.0), abs(auto[key] - e_post))
    fixed_time, auto_time = statistics.median(times["1e-5"]), statistics.median(times["auto"])
    ratio = auto_time / fixed_time
    print(f"restitution --laws all --restitution 0.1:1.0:0.1 --jobs 1 ({len(fixed)} runs), "
          f"median of {repeat}: fixed 1e-5 s {fixed_time:.2f} s, auto {auto_time:.3f} s, ratio "
          f"{ratio:.4f} ({'ok' if ratio <= AUTO_GOAL else 'ABOVE GOAL'} <= {AUTO_GOAL}); "
          f"largest |e_post(auto) - e_post(1e-5 s)|: hertz family "
          f"{worst['hertz family']:.2e} (<= 2e-3), kelvin-voigt {worst['kelvin-voigt']:.2e} "
          f"(<= 5e-3)")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--sweep-repeat", type=int, default=1)
    parser.add_argument("--sweep-only", action="store_true")
    args = parser.parse_args()
    same = True
    with tempfile.TemporaryDirectory() as scratch:
        if not args.sweep_only:
            same = jobs_ratios(args.binary, args.repeat, scratch)
        sweep_ratio(args.binary, args.sweep_repeat, scratch)
    return 0 if same else 1


def read_sweep(path):
    """(law, restitution) -> restitution_post of a `restitution` CSV."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {(r["law"], r["restitution"]): float(r["restitution_post"]) for r in rows}


if __name__ == "__main__":
    sys.exit(main())
