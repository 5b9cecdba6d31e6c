#!/usr/bin/env bash
# Records what the contactlaws program does, byte for byte, into a directory,
# so that a change meant to keep behaviour (a restructuring) can be checked:
#
#   scripts/behaviour_snapshot.sh /tmp/before build/contactlaws   # at the old commit
#   scripts/behaviour_snapshot.sh /tmp/after  build/contactlaws   # at the new one
#   diff -r /tmp/before /tmp/after && echo identical
#
# Each case leaves CASE.out (stdout), CASE.err (stderr), CASE.status (exit
# status) and the files it wrote. Covered: the paper's sweep (fixed 1e-5 s and
# auto), compare on both scenes (its three files) with --jobs 1 and 2, run's
# trajectory and impact log, check, laws, and a set of refusals (tags and
# options). Takes about a minute on 2 cores.
set -euo pipefail

out="${1:?usage: behaviour_snapshot.sh OUTDIR [CONTACTLAWS]}"
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cl="$(realpath "${2:-$repo/build/contactlaws}")"
rm -rf "$out"
mkdir -p "$out/scenes"
out="$(realpath "$out")"
cd "$repo"

ball=mjcf/bouncing_ball.xml
table=mjcf/ball_table.xml

# case NAME ARGS...: runs the program in $out, keeps stdout, stderr, status
case_() {
  local name="$1"
  shift
  local status=0
  (cd "$out" && "$cl" "$@" >"$name.out" 2>"$name.err") || status=$?
  echo "$status" >"$out/$name.status"
}

# the paper's sweep, fixed and auto, and the jobs
case_ sweep_fixed restitution "$repo/$ball" --laws all --dissipation 0.1 --restitution 0.1:1.0:0.1 --jobs 1 --quiet
case_ sweep_auto restitution "$repo/$ball" --laws all --dissipation 0.1 --restitution 0.1:1.0:0.1 --timestep auto \
  --jobs 2 --quiet
for scene in ball table; do
  path="$repo/$ball"
  [ "$scene" = table ] && path="$repo/$table"
  case_ "compare_${scene}_j1" compare "$path" --laws all --dissipation 0.1 --restitution 0.9,0.5 --duration 1 \
    --output-dir "compare_${scene}_j1" --jobs 1 --quiet
  case_ "compare_${scene}_j2" compare "$path" --laws all --dissipation 0.1 --restitution 0.9,0.5 --duration 1 \
    --output-dir "compare_${scene}_j2" --jobs 2 --quiet
  case_ "run_${scene}" run "$path" --duration 1 --output "run_${scene}.csv" \
    --impacts "run_${scene}_impacts.csv"
  case_ "run_${scene}_auto" run "$path" --duration 1 --timestep auto --law kelvin-voigt \
    --restitution 0.5 --output "run_${scene}_auto.csv" --impacts "run_${scene}_auto_impacts.csv"
  case_ "check_${scene}" check "$path"
done
case_ run_stdout run "$repo/$ball" --duration 0.5 --sample-rate 100 --output -
case_ run_euler_coarse run "$repo/$ball" --duration 1 --integrator euler --timestep 1e-3
case_ laws laws
case_ help_run run --help

# refusals of options
case_ bad_law run "$repo/$ball" --law hooke
case_ bad_restitution run "$repo/$ball" --restitution 1.5
case_ bad_restitution_hex run "$repo/$ball" --restitution 0x1p-1 --duration 0.01
case_ bad_timestep run "$repo/$ball" --timestep fast
case_ bad_duration run "$repo/$ball" --duration -1
case_ bad_duration_text run "$repo/$ball" --duration abc
case_ bad_duration_hex run "$repo/$ball" --duration 0x1p-4
case_ bad_timestep_hex run "$repo/$ball" --timestep 0x1p-16 --duration 0.01
case_ bad_jobs_text compare "$repo/$ball" --jobs two
case_ bad_impact_velocity check "$repo/$ball" --impact-velocity 1e999
case_ bad_jobs compare "$repo/$ball" --jobs 0
case_ bad_max_timestep run "$repo/$ball" --max-timestep 1e-3
case_ bad_list restitution "$repo/$ball" --restitution 0.5,0.5
case_ bad_range restitution "$repo/$ball" --restitution 0.9:0.1:0.1
case_ bad_laws compare "$repo/$ball" --laws hertz,hooke
case_ bad_integrator run "$repo/$ball" --integrator rk5
case_ missing_scene run no-such-scene.xml
case_ unknown_option run "$repo/$ball" --frobnicate

# refusals of tags: the ball scene with the tag's data replaced
bad_tags=(
  "geom1=ball geom2=floor law=hooke stiffness=1e8"
  "geom1=ball geom2=floor law=flores restitution=0.5 stiffness=1e8 restitusion=0.5"
  "geom2=floor law=hertz stiffness=1e8"
  "geom1=bal geom2=floor law=hertz stiffness=1e8"
  "geom1=group:5 geom2=floor law=hertz stiffness=1e8"
  "geom1=ball geom2=floor law=hertz stiffness=1e8x"
  "geom1=ball geom2=floor law=hertz stiffness=0x10"
  "geom1=ball geom2=floor law=flores restitution=nan stiffness=1e8"
  "geom1=ball geom2=floor law=hertz stiffness=1e999"
  "geom1=ball geom2=floor law=flores restitution=1.5 stiffness=1e8"
  "geom1=ball geom2=floor law=flores restitution=0 stiffness=1e8"
  "geom1=ball geom2=floor law=hertz stiffness=-1"
  "geom1=ball geom2=floor law=hertz stiffness=1e8 exponent=5"
  "geom1=ball geom2=floor law=hertz youngs1=-2 poisson1=0.3 youngs2=2e11 poisson2=0.3"
  "geom1=ball geom2=floor law=hertz youngs1=2e11 poisson1=0.3"
  "geom1=ball geom2=floor law=kelvin-voigt restitution=0.5 stiffness=1e8 exponent=1.5"
  "geom1=ball geom2=floor law=hunt-crossley stiffness=1e8"
  "geom1=ball geom2=floor law=hertz stiffness=1e8 allow_tension=maybe"
  "geom1=ball geom2=ball law=hertz stiffness=1e8"
  "geom1=ball geom2=floor law=hertz stiffness=1e8 damping=-1"
)
bad_drives=(
  "body=table motion=square axis=z amplitude=0.01 omega=10"
  "body=tabel motion=sine axis=z amplitude=0.01 omega=10"
  "body=table motion=sine axis=0,0,0 amplitude=0.01 omega=10"
  "body=table motion=sine axis=z omega=10"
)

# bad_scenes KIND SCENE PREFIX COMMANDS DATA...: SCENE with the data="..."
# that follows PREFIX (a sed pattern on the same line) replaced by each DATA,
# run by each of COMMANDS
bad_scenes() {
  local kind="$1" source="$2" prefix="$3" commands="$4"
  shift 4
  local k=0 data scene command
  for data in "$@"; do
    k=$((k + 1))
    scene="scenes/bad_${kind}_$k.xml"
    sed "s|\($prefix\)data=\"[^\"]*\"|\1data=\"$data\"|" "$source" >"$out/$scene"
    for command in $commands; do
      case_ "bad_${kind}_${k}_${command}" "$command" "$scene"
    done
  done
}
bad_scenes tag "$ball" ' *' "run check" "${bad_tags[@]}"
bad_scenes drive "$table" 'name="contactdrive:[^"]*" *' "run" "${bad_drives[@]}"
echo "behaviour_snapshot: $(ls "$out" | wc -l) entries in $out"
