#!/bin/sh
# Seconds per evaluation of a fit on the 300 cube tosses (tosses 0-299 of
# data/cube_tosses/train.csv.gz, the shipped mjcf/cube_toss.xml as it runs
# by default: auto timestep, each toss from its first sample): `contactlaws
# fit ... --params mu=0.1:0.3 --budget 4 --jobs JOBS`, its ranking.csv's
# wall_seconds / evaluations, and the process's CPU time (user + system) per
# evaluation beside it (on a loaded machine the wall time also counts the
# waits for a core). Given two programs, their runs alternate; every run is
# printed, then the medians and their ratio (second / first); the load
# average before and after.
#   bench/fit_evaluation_seconds.sh [PROGRAM [OTHER_PROGRAM]] [RUNS] [JOBS]
set -eu
cd "$(dirname "$0")/.."
first=${1:-build/contactlaws}
second=${2:-}
runs=${3:-3}
jobs=${4:-2}
exec /usr/bin/python3 - "$first" "$second" "$runs" "$jobs" <<'PY'
import csv, os, resource, statistics, subprocess, sys, tempfile
first, second, runs, jobs = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
programs = [p for p in (first, second) if p]
work = tempfile.mkdtemp(prefix="fit_evaluation_seconds.")
data = os.path.join(work, "tosses.csv")
subprocess.run(["scripts/cube_tosses_to_csv.py", "data/cube_tosses/train.csv.gz", data,
                "--tosses", "0:300"], check=True, stdout=subprocess.DEVNULL)

def once(program):
    """Wall and CPU seconds per evaluation of one fit."""
    out = os.path.join(work, "fit")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([program, "fit", "mjcf/cube_toss.xml", "--data", data, "--params",
                    "mu=0.1:0.3", "--budget", "4", "--jobs", jobs, "--quiet", "--output", out],
                   check=True, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(out, "ranking.csv")) as f:
        row = next(csv.DictReader(f))
    evaluations = int(row["evaluations"])
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    # the CPU time is the whole process's: loading and the final statistics
    # included, so it is an upper bound of the evaluations' own
    return float(row["wall_seconds"]) / evaluations, cpu / evaluations

print(f"load average before: {os.getloadavg()[0]:.2f}")
wall = {p: [] for p in programs}
cpu = {p: [] for p in programs}
for run in range(runs):
    for p in programs:
        w, c = once(p)
        wall[p].append(w)
        cpu[p].append(c)
        print(f"run {run + 1} {p}: {w:.3f} s wall per evaluation ({c:.3f} s CPU, whole process)")
for p in programs:
    print(f"median {p}: {statistics.median(wall[p]):.3f} s wall, "
          f"{statistics.median(cpu[p]):.3f} s CPU per evaluation")
if second:
    print(f"ratio {second} / {first}: wall "
          f"{statistics.median(wall[second]) / statistics.median(wall[first]):.3f}, CPU "
          f"{statistics.median(cpu[second]) / statistics.median(cpu[first]):.3f}")
print(f"load average after: {os.getloadavg()[0]:.2f}")
PY
