#!/usr/bin/python3
"""What writing trajectory rows costs a run: CPU time (user + system) of
`contactlaws run SCENE` with `--output FILE` against the same run without it,
the two alternated, with the median of each and the median of the
ratios of the runs next to each other (which a machine's speed drifting
from one minute to the next moves less).

The default scene is 49 balls bouncing for 20 s under `--timestep auto
--accuracy 1e-5` at 1000 rows/s (`drop_masked.xml` from
`build/tests/bench/auto_cost write DIR`): 20,001 rows of 649 numbers, 104 MB.
`--load N` keeps N processes busy meanwhile, as a CI machine that runs other
jobs is.

  /usr/bin/python3 bench/row_output_cost.py build/contactlaws --repeats 7 --load 1
"""

import argparse
import multiprocessing
import os
import resource
import statistics
import subprocess
import sys
import tempfile


def spin():
    while True:
        pass


def cpu_seconds(command):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    user = after.ru_utime - before.ru_utime
    system = after.ru_stime - before.ru_stime
    return user, system


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("program", help="the contactlaws binary")
    parser.add_argument("--scene", help="default: drop_masked.xml written by auto_cost")
    parser.add_argument("--formats", nargs="+", default=["npz"], choices=["npz", "csv"])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--load", type=int, default=0, help="busy processes meanwhile")
    parser.add_argument("--duration", default="20")
    args = parser.parse_args()
    if args.repeats < 1 or args.load < 0:
        sys.exit(f"row_output_cost: --repeats {args.repeats} must be >= 1 and "
                 f"--load {args.load} >= 0")

    with tempfile.TemporaryDirectory() as work:
        scene = args.scene
        if scene is None:
            auto_cost = os.path.join(os.path.dirname(os.path.abspath(args.program)),
                                     "tests", "bench", "auto_cost")
            subprocess.run([auto_cost, "write", work], check=True, stdout=subprocess.DEVNULL)
            scene = os.path.join(work, "drop_masked.xml")
        run = [args.program, "run", scene, "--timestep", "auto", "--accuracy", "1e-5",
               "--duration", args.duration]
        variants = {"none": run}
        for f in args.formats:
            variants[f] = run + ["--output", os.path.join(work, "rows." + f)]

        spinners = [multiprocessing.Process(target=spin, daemon=True) for _ in range(args.load)]
        for s in spinners:
            s.start()
        try:
            times = {name: [] for name in variants}
            for _ in range(args.repeats):
                for name, command in variants.items():
                    times[name].append(cpu_seconds(command))
        finally:
            for s in spinners:
                s.terminate()

        base = [u + s for u, s in times["none"]]
        print(f"load {args.load}, {args.repeats} alternated runs, medians of user + system CPU:")
        for name, samples in times.items():
            total = statistics.median(u + s for u, s in samples)
            user = statistics.median(u for u, _ in samples)
            system = statistics.median(s for _, s in samples)
            ratios = sorted((u + s) / b for (u, s), b in zip(samples, base))
            print(f"  {name:5s} {total:.3f} s (user {user:.3f}, system {system:.3f})"
                  f"  ratio of medians {total / statistics.median(base):.3f},"
                  f" median ratio {statistics.median(ratios):.3f}"
                  f" [{ratios[0]:.3f}, {ratios[-1]:.3f}]")


if __name__ == "__main__":
    main()
