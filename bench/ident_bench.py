#!/usr/bin/python3
"""Prints what one evaluation of a fit costs on the cube tosses, and the ratio of in-process
rollouts (`contactlaws replay`) to spawning `contactlaws run` once per toss (targets:
<= 1 s of wall time for the 300 tosses on 2 cores; >= 5x).

    bench/ident_bench.py [build/contactlaws] [--jobs 2] [--repeat 3]

Both sides simulate the same 300 tosses from the same start states at the published 1/1480 s
step and write their trajectories at 148 Hz; the spawned side writes one scene per toss (the
start state as its keyframe) and runs them `--jobs` at a time, and is not charged for scoring.
The medians of --repeat alternating runs; the machine's load is printed beside them.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, "scripts"))
from cube_tosses_to_csv import rotate  # noqa: E402
STEP = "6.756756756756757e-4"


def rotate_back(q, v):
    """R(q)^T v for the unit quaternion q = (w, x, y, z)."""
    w, x, y, z = q
    return rotate((w, -x, -y, -z), v)


def timed(command):
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program", nargs="?", default=os.path.join(REPO, "build/contactlaws"))
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="ident_bench.")
    data = os.path.join(work, "tosses.csv")
    subprocess.run([os.path.join(REPO, "scripts/cube_tosses_to_csv.py"),
                    os.path.join(REPO, "data/cube_tosses/train.csv.gz"), data], check=True)
    replay = [args.program, "replay", os.path.join(REPO, "mjcf/cube_toss.xml"), "--data", data,
              "--start", "refit", "--timestep", STEP, "--jobs", str(args.jobs)]
    # the start states and durations, from a replay's simulated trajectories
    subprocess.run(replay + ["--output", os.path.join(work, "replayed")], check=True,
                   stdout=subprocess.DEVNULL)
    starts = {}
    with open(os.path.join(work, "replayed/trajectories.csv")) as f:
        header = f.readline().strip().split(",")
        for line in f:
            row = dict(zip(header, line.strip().split(",")))
            toss = row["trajectory"]
            if toss not in starts:
                starts[toss] = [row, 0.0]
            starts[toss][1] = float(row["time"]) - float(starts[toss][0]["time"])
    with open(os.path.join(REPO, "mjcf/cube_toss.xml")) as f:
        scene = f.read()
    spawns = []
    for toss, (row, duration) in starts.items():
        c = lambda q: float(row[f"cube.{q}"])  # noqa: E731
        quat = (c("qw"), c("qx"), c("qy"), c("qz"))
        w_body = rotate_back(quat, (c("wx"), c("wy"), c("wz")))
        qpos = [c("x"), c("y"), c("z"), *quat]
        qvel = [c("vx"), c("vy"), c("vz"), *w_body]
        key = (f'<keyframe><key qpos="{" ".join(map(repr, qpos))}" '
               f'qvel="{" ".join(map(repr, qvel))}"/></keyframe>\n</mujoco>')
        path = os.path.join(work, f"toss{toss}.xml")
        with open(path, "w") as out:
            out.write(scene.replace("</mujoco>", key))
        spawns.append([args.program, "run", path, "--duration", f"{duration:.9f}", "--timestep", STEP,
                       "--sample-rate", "148", "--columns", "bodies", "--output",
                       os.path.join(work, f"toss{toss}.csv")])

    def spawn_all():
        start = time.perf_counter()
        running = []
        for command in spawns:
            while len(running) >= args.jobs:
                running.pop(0).wait()
            running.append(subprocess.Popen(command, stdout=subprocess.DEVNULL,
                                            stderr=subprocess.DEVNULL))
        for p in running:
            p.wait()
        return time.perf_counter() - start

    in_process, spawned = [], []
    for _ in range(args.repeat):
        in_process.append(timed(replay))
        spawned.append(spawn_all())
    a, b = statistics.median(in_process), statistics.median(spawned)
    load = os.getloadavg()[0]
    print(f"ident_bench: {len(spawns)} tosses, {args.jobs} jobs, load {load:.1f} on "
          f"{os.cpu_count()} cores, medians of {args.repeat}")
    print(f"  one evaluation in process (contactlaws replay): {a:.3f} s wall (goal <= 1 s)")
    print(f"  spawning contactlaws run per toss:              {b:.3f} s wall")
    print(f"  ratio spawned / in process: {b / a:.2f} (goal >= 5)")


if __name__ == "__main__":
    main()
