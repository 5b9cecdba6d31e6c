// Copyright contactlaws authors.
//
// The loop of plugin_steps.c through the linked library: ContactData's
// BeforeStep(); mj_step; AfterStep() (what the plugin's mj_step does, less
// its lookup and the contact points it appends for the viewer).
//
//   linked_steps SCENE STEPS

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "contactlaws/contactlaws.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: linked_steps SCENE STEPS\n");
    return 1;
  }
  contactlaws::UniqueModel model = contactlaws::LoadModelFile(argv[1]);
  const mjModel* m = model.get();
  contactlaws::UniqueData data(mj_makeData(m));
  mjData* d = data.get();
  const contactlaws::ContactModel laws(m, argv[1]);
  contactlaws::ContactData contacts(laws, d);
  const long steps = std::atol(argv[2]);
  const auto start = std::chrono::steady_clock::now();
  for (long i = 0; i < steps; ++i) contacts.Step();
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  std::printf("%.1f ns per step, t = %.6f s, z = %.9f\n", 1e9 * seconds.count() / steps, d->time,
              d->qpos[2]);
  return 0;
}
