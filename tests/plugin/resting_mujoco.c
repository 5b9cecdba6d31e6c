/* Copyright contactlaws authors.

   A plain MuJoCo 2.2 program in C that knows nothing of contactlaws, as
   mujoco-simulate starts a scene: plugin_test runs it with
   libcontactlaws_plugin.so preloaded and CONTACTLAWS_SETTLE.

     resting_mujoco SCENE.xml STEPS

   Makes one mjData (at qpos0) and prints the height of the first free body
   (qpos[2]), steps it STEPS times with mj_step and prints the largest
   distance it moved from that height, then resets it with mj_resetData and
   prints the height again: "start=Z moved=DZ reset=Z", to 17 digits. */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <mujoco/mujoco.h>

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: resting_mujoco SCENE.xml STEPS\n");
    return 1;
  }
  char error[1000] = "";
  mjModel* m = mj_loadXML(argv[1], NULL, error, sizeof(error));
  if (!m) {
    fprintf(stderr, "resting_mujoco: %s: %s\n", argv[1], error);
    return 1;
  }
  mjData* d = mj_makeData(m);
  const double start = d->qpos[2];
  double moved = 0;
  for (int i = 0, steps = atoi(argv[2]); i < steps; ++i) {
    mj_step(m, d);
    if (fabs(d->qpos[2] - start) > moved) moved = fabs(d->qpos[2] - start);
  }
  mj_resetData(m, d);
  printf("start=%.17g moved=%.17g reset=%.17g\n", start, moved, d->qpos[2]);
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
