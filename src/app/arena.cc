// Copyright contactlaws authors.

#include "app/arena.h"

#include <algorithm>
#include <cstdlib>
#include <string_view>

#include "contactlaws/contact_model.h"
#include "mujoco/hooks.h"

namespace contactlaws::app {
namespace {

// MuJoCo 2.2.2's compiler (user_model.cc): njmax when the scene gives none.
constexpr int kMujocoDefaultNjmax = 500;

// MuJoCo 2.2.2's compiler's nstack when the scene gives none, for njmax rows:
// max(1000, 5 (njmax + neq + nv)^2 + 20 (sizes)).
long MujocoStackHeuristic(const mjModel* m, long njmax) {
  const long rows = njmax + m->neq + m->nv;
  const long sizes = m->nq + m->nv + m->nu + m->na + m->nbody + m->njnt + m->ngeom + m->nsite +
                     m->neq + m->ntendon + m->nwrap;
  return std::max(1000L, 5 * rows * rows + 20 * sizes);
}

// mjtNum the passive hook takes from the stack per evaluation: two 3 x nv
// Jacobians and two nv vectors (src/mujoco/kinematics.cc), with the energy
// ledger's nv (Simulation::Energy) and room for a second pair.
long HookStack(const mjModel* m) { return 2 * (8 * static_cast<long>(m->nv) + m->nv); }

// Rows of a connect, weld, joint, tendon or distance equality: at most 6.
constexpr int kMaxEqualityRows = 6;

// The constraint rows a scene without contact constraints can make: its
// equalities, friction losses and limits (one row each).
long RowsWithoutContacts(const mjModel* m) {
  long rows = kMaxEqualityRows * static_cast<long>(m->neq);
  for (int v = 0; v < m->nv; ++v) rows += m->dof_frictionloss[v] > 0;
  for (int j = 0; j < m->njnt; ++j) rows += m->jnt_limited[j] != 0;
  for (int t = 0; t < m->ntendon; ++t) {
    rows += (m->tendon_frictionloss[t] > 0) + (m->tendon_limited[t] != 0);
  }
  return rows;
}

}  // namespace

void SizeArena(mjModel* m, const ContactModel& cm) {
  const bool defaults = m->njmax == kMujocoDefaultNjmax &&
                        m->nstack == MujocoStackHeuristic(m, kMujocoDefaultNjmax);
  if (!defaults || HasUntaggedContacts(cm)) return;
  m->njmax = static_cast<int>(RowsWithoutContacts(m));
  m->nstack = static_cast<int>(MujocoStackHeuristic(m, m->njmax) + HookStack(m));
}

UniqueModel LoadSizedModel(const std::string& path, const Overrides& overrides) {
  UniqueModel model = LoadModelFile(path);
  const char* option = std::getenv("CONTACTLAWS_ARENA");
  if (option && std::string_view(option) == "mujoco") return model;
  try {
    const ContactModel tags(model.get(), path, overrides);
    SizeArena(model.get(), tags);
  } catch (const Error&) {
    // refused by the run that reads the tags, with this message
  }
  return model;
}

}  // namespace contactlaws::app
