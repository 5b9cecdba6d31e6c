#!/usr/bin/env bash
# Peer comparison with Simbody (tools/peer/README.md): contactlaws'
# Hunt-Crossley bouncing ball against Simbody's HuntCrossleyForce on the same
# ball, e_post error and whole-process wall time, alternating runs, medians.
#
#   bench/peer_simbody.sh [--contactlaws BIN] [--build-dir DIR] [--no-install]
#                           [-- PEER_COMPARE ARGS...]
#
# Stages, in order:
#   install  libsimbody-dev with apt-get when Simbody's CMake package is absent
#            (needs root; skipped with --no-install)
#   build    tools/peer (standalone CMake project, find_package(Simbody)) into
#            --build-dir DIR (default <repo>/build-peer); not part of
#            scripts/build.sh or scripts/test.sh
#   compare  bench/peer_compare.py --contactlaws BIN (default
#            <repo>/build/contactlaws) --simbody DIR/simbody_ball, which runs
#            both processes --runs N times (default 11) at e = 0.8 and 0.5
# Arguments after -- go to peer_compare.py, e.g. -- --runs 21 --accuracy 1e-7.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
contactlaws="$repo/build/contactlaws"
build_dir="$repo/build-peer"
install=1
compare_args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --contactlaws) contactlaws="$(realpath -m "$2")"; shift 2 ;;
    --build-dir) build_dir="$(realpath -m "$2")"; shift 2 ;;
    --no-install) install=0; shift ;;
    --) shift; compare_args=("$@"); break ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    *) echo "peer_simbody.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done

have_simbody() {
  [[ -f /usr/lib/x86_64-linux-gnu/cmake/simbody/SimbodyConfig.cmake ]] ||
    compgen -G "/usr/lib/*/cmake/simbody/SimbodyConfig.cmake" >/dev/null ||
    dpkg -s libsimbody-dev >/dev/null 2>&1
}

if ! have_simbody; then
  if [[ $install -eq 0 ]]; then
    echo "peer_simbody.sh: Simbody not found; install libsimbody-dev" >&2; exit 1
  fi
  echo "== install libsimbody-dev" >&2
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq libsimbody-dev
fi

echo "== build tools/peer into $build_dir" >&2
cmake -S "$repo/tools/peer" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build_dir" -j 1 >/dev/null

echo "== compare" >&2
exec python3 "$repo/bench/peer_compare.py" --contactlaws "$contactlaws" \
  --simbody "$build_dir/simbody_ball" "${compare_args[@]}"
