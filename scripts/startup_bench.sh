#!/bin/sh
# The start-up of `contactlaws run SCENE --duration 1e-5` against a bare MuJoCo
# program that loads the scene and makes its data with MuJoCo's defaults
# (tests/bench/bare_start.c): whole-process wall times of alternating runs,
# medians, and their ratio (issue 15's goal: <= 0.5).
#   scripts/startup_bench.sh [BUILD_DIR] [RUNS] [SCENE]
set -eu
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${2:-41}
scene=${3:-mjcf/bouncing_ball.xml}
for bin in "$build/contactlaws" "$build/tests/bench/bare_start"; do
  [ -x "$bin" ] || { echo "startup_bench.sh: $bin missing: build first (scripts/build.sh)" >&2; exit 2; }
done
exec /usr/bin/python3 - "$build" "$runs" "$scene" <<'PY'
import statistics, subprocess, sys, time
build, runs, scene = sys.argv[1], int(sys.argv[2]), sys.argv[3]
commands = {
    "contactlaws run --duration 1e-5": [f"{build}/contactlaws", "run", scene, "--duration", "1e-5"],
    "bare MuJoCo load + make data": [f"{build}/tests/bench/bare_start", scene],
}
times = {name: [] for name in commands}
for _ in range(runs):
    for name, command in commands.items():
        start = time.perf_counter()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        times[name].append(time.perf_counter() - start)
medians = {name: statistics.median(t) for name, t in times.items()}
for name, m in medians.items():
    print(f"{name:36s} median {1e3 * m:7.2f} ms over {runs} alternating runs")
names = list(commands)
print(f"ratio run / bare: {medians[names[0]] / medians[names[1]]:.3f} (goal <= 0.5)")
PY
