#!/usr/bin/env bash
# Installs missing dependencies, then configures and builds contactlaws
# (Release) into <repo>/build. Works from any working directory.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

bash scripts/install-deps.sh
source scripts/generator.sh
# shellcheck disable=SC2046  # the generator's words, or none
cmake -S "$repo" -B "$repo/build" $(generator_args "$repo/build") -DCMAKE_BUILD_TYPE=Release
cmake --build "$repo/build" -j"$(nproc)"
