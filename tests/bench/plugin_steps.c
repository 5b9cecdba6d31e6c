/* Copyright contactlaws authors.

   The plugin's cost per step: a plain MuJoCo program (libmujoco alone) that
   steps a scene and prints the wall time per mj_step. bench/plugin_bench.sh
   runs it with and without libcontactlaws_plugin.so preloaded, beside
   linked_steps (the same loop through the linked library).

     plugin_steps SCENE STEPS */

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <mujoco/mujoco.h>

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: plugin_steps SCENE STEPS\n");
    return 1;
  }
  char error[1000] = "";
  mjModel* m = mj_loadXML(argv[1], NULL, error, sizeof(error));
  if (!m) {
    fprintf(stderr, "plugin_steps: %s\n", error);
    return 1;
  }
  mjData* d = mj_makeData(m);
  long steps = atol(argv[2]);
  struct timespec start, end;
  clock_gettime(CLOCK_MONOTONIC, &start);
  for (long i = 0; i < steps; ++i) mj_step(m, d);
  clock_gettime(CLOCK_MONOTONIC, &end);
  double seconds = (end.tv_sec - start.tv_sec) + 1e-9 * (end.tv_nsec - start.tv_nsec);
  printf("%.1f ns per step, t = %.6f s, z = %.9f\n", 1e9 * seconds / steps, d->time, d->qpos[2]);
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
