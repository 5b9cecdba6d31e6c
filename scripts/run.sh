#!/usr/bin/env bash
# The main job: builds contactlaws, then simulates the bouncing ball of
# mjcf/bouncing_ball.xml with each of the five laws (restitution 0.8, 2 s),
# writing results/ball_<law>.csv (trajectory) and results/impacts_<law>.csv
# (impact log), and printing each run's summary table.
# Issue 3 replaces this loop with `contactlaws compare` and the figures.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

bash scripts/build.sh

laws=(hertz kelvin-voigt hunt-crossley lankarani-nikravesh flores)

mkdir -p results
for law in "${laws[@]}"; do
  echo
  echo "== ${law} =="
  build/contactlaws run mjcf/bouncing_ball.xml --law "$law" --restitution 0.8 \
    --duration 2 --output "results/ball_${law}.csv" \
    --impacts "results/impacts_${law}.csv"
done
echo
echo "Results in ${repo}/results/"
