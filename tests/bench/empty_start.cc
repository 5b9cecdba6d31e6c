// Copyright contactlaws authors.
//
// The floor under `contactlaws run`'s start-up (bench/startup_bench.sh): a
// program that does nothing, linked to the command line's shared libraries
// (libmujoco and what it needs, libfmt, libstdc++). The dynamic loader, the
// libraries' initialisers and the kernel's exec and exit are what it costs.

int main() { return 0; }
