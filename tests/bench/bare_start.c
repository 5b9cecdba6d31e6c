/* Copyright contactlaws authors.
 *
 * The bare MuJoCo start-up that `contactlaws run SCENE --duration 1e-5` is
 * measured against (bench/startup_bench.sh): load the scene with MuJoCo,
 * make its data with MuJoCo's defaults, free both. */

#include <stdio.h>

#include <mujoco/mujoco.h>

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: bare_start SCENE.xml\n");
    return 2;
  }
  char error[1000] = "";
  mjModel* m = mj_loadXML(argv[1], NULL, error, sizeof(error));
  if (!m) {
    fprintf(stderr, "bare_start: %s: %s\n", argv[1], error);
    return 1;
  }
  mjData* d = mj_makeData(m);
  if (!d) return 1;
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
