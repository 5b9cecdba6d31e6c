#!/usr/bin/env bash
# The test command of the README, and what CI runs (.ci/run execs this script).
#
# Stages, one function each, run in order by main() (each prints its wall
# time; the first that fails stops the script with a non-zero status):
#   build     scripts/build.sh: missing Debian packages, Release configure+build
#   run_ctest ctest on build/: every test of tests/, among them
#             consumer_build_tree and consumer_installed (a find_package
#             consumer built against this build tree, and against an install
#             of it in a temporary prefix) and tag_fuzzer_replay (the fuzz
#             corpus and regressions, no libFuzzer)
#   asan      build-asan/: the whole suite again under AddressSanitizer +
#             UndefinedBehaviorSanitizer
#   tsan      build-tsan/: hooks_test and shared_model_test (threads) under
#             ThreadSanitizer
#   fuzz      build-fuzz/: the libFuzzer target tag_fuzzer for about 60 s on a
#             scratch copy of its corpus (only where clang and libFuzzer are)
#   pip       not by default (a whole build of the module, minutes cold):
#             python_pip_notebook (label pip), the README's pip install into
#             a venv and the notebook on its kernel (docs/testing.md)
# libmujoco itself is not instrumented: the sanitizers see this project's code
# (and malloc/free everywhere), not MuJoCo's own memory accesses.
#
#   scripts/test.sh                 every stage
#   scripts/test.sh asan tsan       only these (after a build, for instance)
#   FUZZ_SECONDS=300 scripts/test.sh fuzz
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"
source scripts/generator.sh

jobs=2  # the machine's cores; ctest -j and the builds
# 30 s of fuzzing keeps scripts/test.sh under CI's 15 minutes; the corpus and
# the regressions also run in ctest (tag_fuzzer_replay), and a longer search
# is FUZZ_SECONDS=300 scripts/test.sh fuzz
fuzz_seconds="${FUZZ_SECONDS:-30}"
stage_times=()

# The compiler of the sanitizer builds: clang when installed (its libFuzzer
# and sanitizer runtimes come with libclang-rt-14-dev), else g++.
sanitizer_cxx() {
  if command -v clang++ >/dev/null 2>&1; then echo clang++; else echo g++; fi
}

# Configures build dir $1 with compiler $2 and sanitizer flags $3 (compile)
# and $4 (link); further arguments go to cmake.
configure_sanitized() {
  local dir="$1" cxx="$2" cflags="$3" lflags="$4"
  shift 4
  # the plugin is left out: a shared library linked with -Wl,--no-undefined
  # cannot take the sanitizers' runtime, which only executables carry (its
  # tests are not run there either: label preload)
  # nor the Python module (its tests cannot load an instrumented module:
  # label python) and the MPI build (label mpi), which no sanitized test runs,
  # nor the benchmarks (label benchmark: not run here).
  # -O1, as the sanitizers' documentation advises, and line tables only for
  # their stack traces: a fifth less compile time than -O2 -g (clang,
  # src/cli/sweep.cc: 6.1 -> 5.0 s of CPU), in trees built for one run
  local debug="-g1"
  if [ "$cxx" = clang++ ]; then debug="-gline-tables-only"; fi
  # shellcheck disable=SC2046  # the generator's words, or none
  cmake -S "$repo" -B "$repo/$dir" $(generator_args "$repo/$dir") -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 $debug -DNDEBUG" \
    -DCONTACTLAWS_BUILD_PLUGIN=OFF -DCONTACTLAWS_PYTHON=OFF -DCONTACTLAWS_MPI=OFF \
    -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON \
    -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_CXX_FLAGS="$cflags" \
    -DCMAKE_EXE_LINKER_FLAGS="$lflags" \
    -DCMAKE_SHARED_LINKER_FLAGS="$lflags" "$@" >/dev/null
}

build() {
  bash scripts/build.sh
}

run_ctest() {
  # The tests run again with contact steps (label contact-steps) are in, but
  # for rolling_test's (label contact-steps-long: 48 s of CPU; `ctest
  # --test-dir build -L contact-steps` runs them all)
  ctest --test-dir build --output-on-failure -j"$jobs" -LE 'pip|contact-steps-long'
}

pip() {
  ctest --test-dir build --output-on-failure -L pip
}

asan() {
  local flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
  configure_sanitized build-asan "$(sanitizer_cxx)" "$flags" "$flags"
  cmake --build build-asan -j"$jobs"
  # Left out: the consumer tests (label consumer: they build a consumer
  # without the sanitizer flags against the instrumented static library,
  # which cannot link, and they check packaging, not memory) and the
  # benchmark smoke run
  # (label benchmark: timings mean nothing here, and it is the slowest);
  # the plugin's tests (label preload: an instrumented libcontactlaws_plugin.so
  # cannot be preloaded into the uninstrumented plain_mujoco and
  # mujoco-simulate, the ASan runtime must come first) and render's (label
  # render: Mesa's driver, loaded into the process, is not ours to check for
  # leaks). AppendVisibleContacts, which both use, is checked here. And the
  # stacks standing 10 s (label slow: three minutes under the sanitizers, for
  # code that box_box_test and the friction tests run here too). And the
  # Python module's pytest (label python: an instrumented module cannot load
  # into Debian's python3) and mpi_test (label mpi: Open MPI's own
  # never-freed allocations are leaks to LeakSanitizer).
  # And by name, the four longest under ASan (61 s of its 250 s of test CPU,
  # a fresh clone on 2 cores), long runs of code that shorter tests here
  # step through too: the auto step's stick spring and resting die (the
  # other AutoTimestepTest cases), the settled plate (SettleTest's others),
  # the reference sweep (SweepTest); all four run in run_ctest.
  local asan_skipped='AutoTimestepTest.TheStickSpringIsResolvedAsTheNormalContactIs'
  asan_skipped+='|SettleTest.ASettledPlateWithBallsStaysAtRestUnderAuto'
  asan_skipped+='|ReferenceTest.SweepAgreesWithTheIndependentIntegration'
  asan_skipped+='|AutoTimestepTest.ARestingDieComesToRestAsAtAFineFixedStep'
  ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1 \
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure -j"$jobs" \
      -LE 'benchmark|consumer|preload|render|slow|python|mpi|contact-steps' -E "$asan_skipped"
}

tsan() {
  local flags="-fsanitize=thread -fno-omit-frame-pointer"
  configure_sanitized build-tsan "$(sanitizer_cxx)" "$flags" "$flags"
  cmake --build build-tsan -j"$jobs" --target hooks_test shared_model_test
  # a report makes the test exit non-zero (exitcode=66), whatever gtest says
  local test
  for test in hooks_test shared_model_test; do
    TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:exitcode=66 \
      "build-tsan/tests/$test"
  done
}

fuzz() {
  if ! command -v clang++ >/dev/null 2>&1; then
    echo "fuzz: clang++ not installed: skipped (scripts/install-deps.sh installs it)"
    return 0
  fi
  # the library is built with coverage (fuzzer-no-link) and the sanitizers;
  # the target links libFuzzer (CMakeLists of tests/fuzz)
  configure_sanitized build-fuzz clang++ \
    "-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
    "-fsanitize=address,undefined" -DCONTACTLAWS_BUILD_FUZZER=ON
  cmake --build build-fuzz -j"$jobs" --target tag_fuzzer
  # a scratch copy of the seeds and the regressions: the fuzzer adds to its
  # corpus directory, and the repository must not change
  local scratch
  scratch="$(mktemp -d)"
  mkdir "$scratch/corpus" "$scratch/artifacts"
  find tests/fuzz/corpus tests/fuzz/regressions -type f ! -name '.*' \
    -exec cp -t "$scratch/corpus/" {} +
  local status=0
  build-fuzz/tests/fuzz/tag_fuzzer -max_total_time="$fuzz_seconds" -print_final_stats=1 \
    -dict=tests/fuzz/tag_fuzzer.dict -artifact_prefix="$scratch/artifacts/" \
    "$scratch/corpus" 2>"$scratch/fuzz.log" || status=$?
  grep -E '^(Done|stat::(number_of_executed_units|average_exec_per_sec|new_units_added))' \
    "$scratch/fuzz.log" || true
  if [ "$status" -ne 0 ] || [ -n "$(ls -A "$scratch/artifacts")" ]; then
    tail -n 60 "$scratch/fuzz.log"
    echo "fuzz: FAILED (status $status). The input that failed, to add under tests/fuzz/regressions/:"
    local artifact
    for artifact in "$scratch"/artifacts/*; do
      [ -e "$artifact" ] || continue
      echo "  $artifact (base64: $(base64 -w0 "$artifact"))"
    done
    return 1
  fi
  rm -rf "$scratch"
}

# Runs stage $1 and records its wall time.
stage() {
  local name="$1" start end
  start=$(date +%s)
  echo "== test.sh: stage $name"
  "$name"
  end=$(date +%s)
  stage_times+=("$name $((end - start)) s")
  echo "== test.sh: stage $name done in $((end - start)) s"
}

main() {
  local stages=("$@")
  if [ "${#stages[@]}" -eq 0 ]; then
    stages=(build run_ctest asan tsan fuzz)
  fi
  for name in "${stages[@]}"; do
    case "$name" in
      build|run_ctest|asan|tsan|fuzz|pip) stage "$name" ;;
      *) echo "test.sh: unknown stage '$name' (build run_ctest asan tsan fuzz pip)" >&2; exit 2 ;;
    esac
  done
  local IFS=','
  echo "== test.sh: every stage passed (${stage_times[*]})"
}

main "$@"
