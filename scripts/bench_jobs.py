#!/usr/bin/env python3
"""--jobs 2 against --jobs 1: wall time as a ratio, and the outputs compared.

    python3 scripts/bench_jobs.py CONTACTLAWS_BINARY [--repeat N]

Runs `restitution` and `compare` on mjcf/bouncing_ball.xml with --jobs 1 and
--jobs 2, alternating, N times each (default 3), and prints the median wall
times and their ratio (issue 5's goal: <= 0.65 on 2 cores). Fails (exit 1)
when the two write different bytes. Wall time, not CPU time: the point of
--jobs is the elapsed time. Standard library only.
"""

import argparse
import filecmp
import os
import statistics
import subprocess
import sys
import tempfile
import time

GOAL = 0.65
SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "mjcf", "bouncing_ball.xml")


def commands(out):
    """name -> (arguments without --jobs, the files it writes)."""
    return {
        "restitution --laws all --restitution 0.2:1.0:0.2 (25 runs, fixed 1e-5 s)": (
            ["restitution", SCENE, "--laws", "all", "--restitution", "0.2:1.0:0.2",
             "--quiet", "--output", os.path.join(out, "e.csv")],
            ["e.csv"]),
        "compare --laws all --restitution 0.3,0.6,0.9 --duration 1 (13 runs)": (
            ["compare", SCENE, "--laws", "all", "--restitution", "0.3,0.6,0.9", "--duration",
             "1", "--quiet", "--output-dir", out],
            ["trajectories.csv", "impacts.csv", "summary.csv"]),
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    print(f"--jobs 2 / --jobs 1, wall time, median of {args.repeat} (goal <= {GOAL}); "
          f"{os.cpu_count()} cores")
    failed = False
    with tempfile.TemporaryDirectory() as scratch:
        dirs = {jobs: os.path.join(scratch, f"jobs{jobs}") for jobs in (1, 2)}
        for d in dirs.values():
            os.makedirs(d)
        for name in commands(scratch):
            times = {1: [], 2: []}
            for _ in range(args.repeat):
                for jobs in (1, 2):
                    arguments, _ = commands(dirs[jobs])[name]
                    start = time.perf_counter()
                    subprocess.run([args.binary, *arguments, "--jobs", str(jobs)], check=True,
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
            failed = failed or not same
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
