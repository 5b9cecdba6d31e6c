# Sourced by scripts/build.sh and scripts/test.sh: the CMake generator of a
# build directory. Ninja (Debian's ninja-build) for a new one: Unix Makefiles
# spend a process or more per object on progress and dependency bookkeeping
# (a build with nothing to do: 12.5 s of CPU with make, 0.2 s with ninja).
# A directory already configured keeps the generator it has, which CMake
# requires.

# Prints the cmake arguments that choose the generator for build dir $1.
generator_args() {
  if [ ! -f "$1/CMakeCache.txt" ] && command -v ninja >/dev/null 2>&1; then
    echo "-G Ninja"
  fi
}
