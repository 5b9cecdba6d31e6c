#!/usr/bin/env bash
# The plugin's overhead per step against the linked library, and the cost of
# one rendered frame, as ratios from one run (docs/performance.md).
#
#   bench/plugin_bench.sh [BUILD_DIR]      (default: build, built Release)
#
# Steps: the paper's ball (mjcf/bouncing_ball.xml, RK4, 1e-5 s) for 200,000
# steps (2 s: flight and five impacts), best of 3 runs each, by
#   plugin_steps            a plain C program, MuJoCo's own contact
#   plugin_steps + plugin   the same, libcontactlaws_plugin.so preloaded
#   linked_steps            ContactData::Step() through the linked library
# Frames: contactlaws render of 2 s of the same ball at 30 fps, 640x480, PNG
# files and MP4, its own "ms per frame drawn" (mjv_updateScene, mjr_render,
# overlay, read back) and its wall time per frame.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$repo/build}"
scene="$repo/mjcf/bouncing_ball.xml"
steps=200000
runs=3

# best ns per step of a command over $runs runs
best() {
  local best=""
  for _ in $(seq "$runs"); do
    local ns
    ns="$("$@" | awk '{print $1}')"
    if [ -z "$best" ] || awk -v a="$ns" -v b="$best" 'BEGIN{exit !(a<b)}'; then best="$ns"; fi
  done
  echo "$best"
}

mujoco="$(best "$build/tests/bench/plugin_steps" "$scene" "$steps")"
plugin="$(best env LD_PRELOAD="$build/libcontactlaws_plugin.so" \
  "$build/tests/bench/plugin_steps" "$scene" "$steps" 2>/dev/null)"
linked="$(best "$build/tests/bench/linked_steps" "$scene" "$steps")"
echo "steps of $scene ($steps, best of $runs), ns per step:"
echo "  MuJoCo's own contact (no plugin)  $mujoco"
echo "  plugin preloaded                  $plugin"
echo "  linked library (ContactData)      $linked"
awk -v p="$plugin" -v l="$linked" -v m="$mujoco" 'BEGIN {
  printf "  plugin / linked = %.3f   plugin - linked = %.0f ns per step   plugin / MuJoCo = %.2f\n",
         p / l, p - l, p / m }'

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
echo "frames of 2 s at 30 fps, 640x480:"
for output in "$tmp/frames/" "$tmp/ball.mp4"; do
  start=$(date +%s.%N)
  line="$("$build/contactlaws" render "$scene" --duration 2 --fps 30 --output "$output" \
    --timestep auto)"
  end=$(date +%s.%N)
  frames="$(echo "$line" | sed -E 's/.*: ([0-9]+) frames.*/\1/')"
  drawn="$(echo "$line" | sed -E 's/.* ([0-9.]+) ms per frame drawn.*/\1/')"
  awk -v s="$start" -v e="$end" -v f="$frames" -v d="$drawn" -v o="${output##*.}" 'BEGIN {
    printf "  %-8s %d frames: %.1f ms per frame drawn, %.1f ms per frame in all (steps, encoding, start-up)\n",
           (o ~ /\// ? "PNG" : o), f, d, 1e3 * (e - s) / f }'
done
