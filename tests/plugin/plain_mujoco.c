/* Copyright contactlaws authors.

   A plain MuJoCo 2.2 program in C that knows nothing of contactlaws: it links
   libmujoco alone. plugin_test runs it with and without
   libcontactlaws_plugin.so preloaded.

     plain_mujoco TAGGED.xml UNTAGGED.xml SPEED

   Each scene is a free ball over a floor, without gravity. Two mjData of
   TAGGED and one of UNTAGGED are given the downward speed SPEED (m/s) and
   stepped together with mj_step until each ball has left the floor again.
   One line per data: its rebound (speed after / speed before), the most
   contacts d->contact held after a step with exclude = 1 (in gap: what the
   plugin appends to show the tagged points) and with exclude = 0 (MuJoCo's
   own), the steps it took, and the final height and vertical speed to 17
   digits. A first line "look" gives TAGGED's lights and textures and its
   first geom's material (what the plugin's CONTACTLAWS_LOOK adds). */

#include <stdio.h>
#include <stdlib.h>

#include <mujoco/mujoco.h>

/* steps after which a ball that has not left the floor is reported as stuck */
#define MAX_STEPS 1000000

typedef struct {
  const char* name;
  mjData* d;
  double speed_in;
  int max_gap_contacts;
  int max_solver_contacts;
  int steps;
  int done;
} Run;

static mjModel* Load(const char* path) {
  char error[1000] = "";
  mjModel* m = mj_loadXML(path, NULL, error, sizeof(error));
  if (!m) {
    fprintf(stderr, "plain_mujoco: %s: %s\n", path, error);
    exit(1);
  }
  return m;
}

static void Start(Run* run, const char* name, mjModel* m, double speed) {
  run->name = name;
  run->d = mj_makeData(m);
  run->d->qvel[2] = -speed; /* free joint: qvel = (v, omega) */
  run->speed_in = speed;
  run->max_gap_contacts = 0;
  run->max_solver_contacts = 0;
  run->steps = 0;
  run->done = 0;
}

/* One step; done once the ball is clear of the floor and moving up. */
static void Step(const mjModel* m, Run* run) {
  mjData* d = run->d;
  double radius = m->geom_size[3 * 1];
  int gap = 0, solver = 0;
  mj_step(m, d);
  ++run->steps;
  for (int i = 0; i < d->ncon; ++i) {
    if (d->contact[i].exclude == 1) ++gap;
    if (d->contact[i].exclude == 0) ++solver;
  }
  if (gap > run->max_gap_contacts) run->max_gap_contacts = gap;
  if (solver > run->max_solver_contacts) run->max_solver_contacts = solver;
  if (d->qvel[2] > 0 && d->qpos[2] > 1.01 * radius) run->done = 1;
}

int main(int argc, char** argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: plain_mujoco TAGGED.xml UNTAGGED.xml SPEED\n");
    return 1;
  }
  double speed = atof(argv[3]);
  mjModel* tagged = Load(argv[1]);
  mjModel* untagged = Load(argv[2]);
  if (tagged) {
    printf("look nlight=%d ntex=%d matid=%d\n", tagged->nlight, tagged->ntex, tagged->geom_matid[0]);
  }
  Run runs[3];
  Start(&runs[0], "tagged0", tagged, speed);
  Start(&runs[1], "tagged1", tagged, speed);
  Start(&runs[2], "untagged", untagged, speed);
  const mjModel* models[3] = {tagged, tagged, untagged};

  /* the three data stepped in turn */
  for (int step = 0; step < MAX_STEPS; ++step) {
    int running = 0;
    for (int k = 0; k < 3; ++k) {
      if (runs[k].done) continue;
      Step(models[k], &runs[k]);
      running = 1;
    }
    if (!running) break;
  }
  for (int k = 0; k < 3; ++k) {
    mjData* d = runs[k].d;
    printf("%s rebound=%.9f gap_contacts=%d solver_contacts=%d steps=%d done=%d z=%.17g "
           "vz=%.17g\n",
           runs[k].name, d->qvel[2] / runs[k].speed_in, runs[k].max_gap_contacts,
           runs[k].max_solver_contacts, runs[k].steps, runs[k].done, d->qpos[2], d->qvel[2]);
    mj_deleteData(d);
  }
  mj_deleteModel(tagged);
  mj_deleteModel(untagged);
  return 0;
}
