#!/usr/bin/env bash
# Installs, only if missing, the Debian 12 packages contactlaws needs to build,
# test and plot. Safe to run repeatedly and without stdin (CI): prints one line
# naming what it installs, or nothing when everything is present.
set -euo pipefail

packages=(
  build-essential
  cmake
  ninja-build         # the builds' generator (scripts/generator.sh)
  libmujoco-dev
  libqhull-dev        # Debian's mujoco CMake config references /usr/include/libqhull_r
  libeigen3-dev
  libfmt-dev
  libgtest-dev
  libcli11-dev
  libbenchmark-dev
  libnlopt-dev        # fit: NLopt's optimisers through its C API (docs/identification.md)
  libcereal-dev       # the serialiser of what a cluster job's ranks exchange (src/ident/wire.h)
  clang               # the sanitizer builds and the fuzzer of scripts/test.sh
  libclang-rt-14-dev  # clang's sanitizer and libFuzzer runtimes
  python3-matplotlib
  python3-numpy
  libmujoco-samples   # mujoco-simulate: contactlaws simulate, and its test
  xvfb                # a virtual X server: mujoco-simulate's test runs under xvfb-run
  xauth               # xvfb-run needs it
  libegl-dev          # contactlaws render: an OpenGL context without a display (EGL)
  libegl-mesa0        # Mesa's EGL: the surfaceless platform, software rendering (llvmpipe)
  libpng-dev          # contactlaws render DIR/: the PNG files, and the render test reads them
  zlib1g-dev          # run --output FILE.npz: the archive's CRC-32s
  ffmpeg              # contactlaws render FILE.mp4|FILE.gif, and ffprobe for its test
  libopenmpi-dev      # CONTACTLAWS_MPI: replay and fit over the ranks of a job (docs/cluster.md)
  openmpi-bin         # mpirun, for mpi_test
  python3-dev         # the Python module (python/): its headers
  pybind11-dev        # the Python module's bindings
  python3-pandas      # the Python module's DataFrames
  python3-pytest      # python_test: pytest on the module
  python3-venv        # pip install . into a venv (docs/python.md)
  jupyter-nbconvert   # python_notebook: jupyter nbconvert --execute examples/quickstart.ipynb
  python3-ipykernel   # the notebook's kernel (Debian's python3, its numpy, pandas, matplotlib)
)

missing=()
for pkg in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"

sudo_cmd=()
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1; then
  sudo_cmd=(sudo)
fi

"${sudo_cmd[@]}" apt-get update < /dev/null
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}" < /dev/null
