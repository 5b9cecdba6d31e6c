#!/usr/bin/env bash
# The test command of the README, and what CI runs (.ci/run execs this script).
#
# Stages, one function each, run in order by main():
#   build     scripts/build.sh: missing Debian packages, Release configure+build
#   run_ctest ctest on build/: every test of tests/, among them
#             consumer_find_package (installs the library into a temporary
#             prefix and builds a find_package consumer against it)
# The script exits with ctest's status: 0 only when every test passed.
# To add a stage (e.g. a sanitizer build in its own build directory), write a
# function and call it from main().
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

build() {
  bash scripts/build.sh
}

run_ctest() {
  ctest --test-dir build --output-on-failure -j2
}

main() {
  build
  run_ctest
}

main "$@"
