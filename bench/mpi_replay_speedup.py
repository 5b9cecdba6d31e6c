#!/usr/bin/python3
"""Measures the MPI speedup of `contactlaws replay` on this machine: of the 300 cube tosses on
2 ranks x 1 thread against the ideal half of 1 rank x 1 thread, for the whole `mpirun` job and for
the command inside it (docs/performance.md).

    bench/mpi_replay_speedup.py [build/contactlaws] [--rounds 5]

Each round runs, one after another: the program alone, `mpirun -np 1` and `mpirun -np 2`, and the
program alone with 2 threads ("threads2": 1 rank x 2 threads, the same split without MPI). Walls
are taken around each process; "command" is the 2-rank job's timing line's wall (rank 0 from its start
to leaving the job: reading, `MPI_Init` beside it, the rollouts, the exchange, writing; see
docs/cluster.md). Medians over the rounds, the load beside them.

What the job spends outside the command (mpirun's start before the ranks run, `MPI_Finalize`,
mpirun's end) is job - command. For the whole job to meet the goal, the command must take at most
1.15 x (1 rank's job) / 2 minus that: the script prints that bound against the ideal half of the
program alone, beside the command's measured ratio and the 2 threads' (the rollouts split on
this machine without any of MPI's costs).
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STEP = "6.756756756756757e-4"  # the published 1/1480 s
GOAL = 1.15
MPIRUN = ["mpirun", "--oversubscribe"]  # two ranks may be more than the cores


def run(command, output):
    """Wall of one process (s), and the timing line's wall when it printed one."""
    start = time.perf_counter()
    done = subprocess.run(command + ["--output", output], stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"mpi_goal: {' '.join(command)} failed ({done.returncode}):\n{done.stderr}")
    timing = re.search(r"^contactlaws: timing: .* wall ([0-9.]+) s", done.stderr, re.M)
    return wall, float(timing.group(1)) if timing else None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program", nargs="?", default=os.path.join(REPO, "build/contactlaws"))
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    if os.geteuid() == 0:
        MPIRUN.append("--allow-run-as-root")
    work = tempfile.mkdtemp(prefix="mpi_goal.")
    every = os.path.join(work, "tosses.csv")
    subprocess.run([os.path.join(REPO, "scripts/cube_tosses_to_csv.py"),
                    os.path.join(REPO, "data/cube_tosses/train.csv.gz"), every], check=True)
    kinds = {"alone": [], "np1": MPIRUN + ["-np", "1"], "np2": MPIRUN + ["-np", "2"],
             "threads2": []}
    walls = {k: [] for k in kinds}
    command_walls, loads = [], []
    for _ in range(args.rounds):
        for kind, launcher in kinds.items():
            replay = launcher + [args.program, "replay", os.path.join(REPO, "mjcf/cube_toss.xml"),
                                 "--data", every, "--start", "refit", "--timestep", STEP,
                                 "--jobs", "2" if kind == "threads2" else "1"]
            wall, timing = run(replay, os.path.join(work, kind))
            walls[kind].append(wall)
            if kind == "np2":
                command_walls.append(timing)
        loads.append(os.getloadavg()[0])

    print(f"{args.rounds} rounds, load {min(loads):.2f}-{max(loads):.2f}; medians, s (min-max):")
    for kind, w in list(walls.items()) + [("np2 command (timing line)", command_walls)]:
        print(f"  {kind:26} {statistics.median(w):.3f} ({min(w):.3f}-{max(w):.3f})")
    alone, np1, np2, threads2 = (statistics.median(walls[k]) for k in kinds)
    command = statistics.median(command_walls)
    outside = np2 - command
    bound = GOAL * np1 / 2 - outside
    print(f"whole job: 2 ranks / (1 rank / 2) = {np2 / (np1 / 2):.3f} (goal {GOAL})")
    print(f"command:   2 ranks' timing line / (program alone / 2) = {command / (alone / 2):.3f}; "
          f"1 rank x 2 threads / (program alone / 2) = {threads2 / (alone / 2):.3f}")
    print(f"a 1-rank job costs {np1 - alone:.3f} s more than the program alone; the 2-rank job "
          f"spends {outside:.3f} s outside its command; so the goal needs the command within "
          f"{bound:.3f} s, {bound / (alone / 2):.3f}x of the ideal half of the program alone; "
          f"2 threads without MPI take {threads2 / (alone / 2):.3f}x")


if __name__ == "__main__":
    main()
