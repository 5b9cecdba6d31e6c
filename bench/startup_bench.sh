#!/bin/sh
# The start-up of `contactlaws run SCENE --duration 1e-5` against a bare MuJoCo
# program that loads the scene and makes its data with MuJoCo's defaults
# (tests/bench/bare_start.c): whole-process wall times of alternating runs,
# medians, and their ratio; then the run with MuJoCo's own arena
# (CONTACTLAWS_ARENA=mujoco) against the bare program again. CPU time (user +
# system) beside each: on a loaded machine the wall time also counts the
# waits for a core. Each process is started with posix_spawn (a vfork, not a
# copy of this Python's page tables: subprocess.Popen added ~0.3 ms to every
# process, both sides), and the floor is printed: an empty main linked to the
# run's libraries (tests/bench/empty_start.cc), what no start-up of ours can
# go below.
#   bench/startup_bench.sh [BUILD_DIR] [RUNS] [SCENE]
set -eu
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${2:-41}
scene=${3:-mjcf/bouncing_ball.xml}
for bin in "$build/contactlaws" "$build/tests/bench/bare_start" "$build/tests/bench/empty_start"; do
  [ -x "$bin" ] || { echo "startup_bench.sh: $bin missing: build first (scripts/build.sh)" >&2; exit 2; }
done
exec /usr/bin/python3 - "$build" "$runs" "$scene" <<'PY'
import os, statistics, subprocess, sys, time
build, runs, scene = sys.argv[1], int(sys.argv[2]), sys.argv[3]
run = [f"{build}/contactlaws", "run", scene, "--duration", "1e-5"]
bare = [f"{build}/tests/bench/bare_start", scene]
empty = [f"{build}/tests/bench/empty_start"]
sized = dict(os.environ)
unsized = dict(os.environ, CONTACTLAWS_ARENA="mujoco")
devnull = os.open(os.devnull, os.O_WRONLY)

def alternate(commands):
    """Wall and CPU medians of the commands run in turn, runs times."""
    wall = {name: [] for name in commands}
    cpu = {name: [] for name in commands}
    for _ in range(runs):
        for name, (command, env) in commands.items():
            start = time.perf_counter()
            pid = os.posix_spawn(command[0], command, env,
                                 file_actions=[(os.POSIX_SPAWN_DUP2, devnull, 1)])
            _, status, usage = os.wait4(pid, 0)
            wall[name].append(time.perf_counter() - start)
            cpu[name].append(usage.ru_utime + usage.ru_stime)
            if status != 0:
                sys.exit(f"startup_bench.sh: {' '.join(command)} failed")
    w = {name: statistics.median(t) for name, t in wall.items()}
    c = {name: statistics.median(t) for name, t in cpu.items()}
    for name in commands:
        print(f"{name:36s} median {1e3 * w[name]:7.2f} ms over {runs} alternating runs"
              f" (CPU {1e3 * c[name]:5.2f} ms)")
    first, second = list(commands)[:2]
    return w[first] / w[second], c[first] / c[second], w, c

subprocess.run(run, check=True, stdout=subprocess.DEVNULL, env=sized)  # warms the page cache
ratio, cpu_ratio, w, c = alternate({
    "contactlaws run --duration 1e-5": (run, sized),
    "bare MuJoCo load + make data": (bare, sized),
    "empty main, the same libraries": (empty, sized)})
print(f"ratio run / bare: {ratio:.3f} (goal <= 0.5) (CPU {cpu_ratio:.3f})")
floor, base = w["empty main, the same libraries"], w["bare MuJoCo load + make data"]
print(f"floor: the libraries alone / bare: {floor / base:.3f}"
      f" (CPU {c['empty main, the same libraries'] / c['bare MuJoCo load + make data']:.3f})")
ratio, cpu_ratio, _, _ = alternate({"run, MuJoCo's arena": (run, unsized),
                                   "bare MuJoCo load + make data": (bare, sized)})
print(f"ratio run with MuJoCo's arena / bare: {ratio:.3f} (CPU {cpu_ratio:.3f})")
PY
