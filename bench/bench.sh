#!/usr/bin/env bash
# The cost of the hooks, friction and the timestep against MuJoCo's own contact, as ratios from one run.
#
#   bench/bench.sh [--build-dir DIR] [--json FILE] [--markdown | --update-doc]
#                    [-- BENCHMARK ARGS...]
#
# Stages, in order:
#   build   Release: scripts/build.sh (<repo>/build), or cmake into --build-dir DIR
#   run     contactlaws_bench once, its JSON to --json FILE (default
#           results/benchmark.json); its console table goes to stderr
#   report  bench/bench_report.py: the ratios (hooks / MuJoCo's own contact,
#           hooks / free flight, ns per law call, cost per step against the
#           number of balls, the sweep), as text; with --markdown as the
#           tables of docs/performance.md; with --update-doc written into
#           docs/performance.md (between its bench:begin/end markers)
#   jobs    bench/bench_jobs.py: --jobs 2 against --jobs 1 of the
#           restitution and compare commands, wall time as a ratio, and their
#           outputs compared byte for byte (skipped with --markdown/--update-doc)
#   auto    tests/bench/auto_cost: the costs of --timestep auto (untagged
#           pairs far apart, trajectory rows, a dense pile) as ratios of CPU
#           time (skipped with --markdown/--update-doc)
# Arguments after -- go to contactlaws_bench, e.g. -- --benchmark_repetitions=3
# (the report then uses the medians) or -- --benchmark_filter=BallBox.
# The benchmarks take about a minute on 2 cores, the build aside.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

invocation="bench/bench.sh${*:+ $*}"  # for the report
build_dir=""
json="$repo/results/benchmark.json"
report_args=()
bench_args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build-dir) build_dir="$(realpath -m "$2")"; shift 2 ;;
    --json) json="$(realpath -m "$2")"; shift 2 ;;
    --markdown) report_args+=(--markdown); shift ;;
    --update-doc) report_args+=(--update-doc "$repo/docs/performance.md"); shift ;;
    --) shift; bench_args=("$@"); break ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "bench.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done

build() {
  if [[ -z "$build_dir" ]]; then
    bash scripts/build.sh >&2
    build_dir="$repo/build"
  else
    cmake -S "$repo" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >&2
    cmake --build "$build_dir" -j"$(nproc)" --target contactlaws_bench auto_cost >&2
  fi
  if [[ ! -x "$build_dir/tests/bench/contactlaws_bench" ]]; then
    echo "bench.sh: no $build_dir/tests/bench/contactlaws_bench (is libbenchmark-dev installed?)" >&2
    exit 1
  fi
}

run() {
  mkdir -p "$(dirname "$json")"
  "$build_dir/tests/bench/contactlaws_bench" --benchmark_out="$json" \
    --benchmark_out_format=json "${bench_args[@]}" >&2
}

report() {
  local revision
  revision="$(git -C "$repo" describe --always --dirty 2>/dev/null || echo "not a git checkout")"
  python3 bench/bench_report.py "$json" --command "$invocation" --revision "$revision" \
    "${report_args[@]}"
}

jobs() {
  python3 bench/bench_jobs.py "$build_dir/contactlaws"
}

auto_costs() {
  "$build_dir/tests/bench/auto_cost"
}

main() {
  build
  run
  report
  if [[ ${#report_args[@]} -eq 0 ]]; then jobs; auto_costs; fi
}

main
