// Copyright contactlaws authors.

#include "mujoco/step_pairs.h"

#include <algorithm>

#include "mujoco/kinematics.h"
#include "mujoco/reach_sweep.h"

namespace contactlaws::internal {
namespace {

// mj_broadphase's can_collide: body b has a geom with contype or conaffinity.
bool CanCollide(const mjModel* m, int b) {
  for (int g = m->body_geomadr[b]; g < m->body_geomadr[b] + m->body_geomnum[b]; ++g) {
    if (m->geom_contype[g] || m->geom_conaffinity[g]) return true;
  }
  return false;
}

// mj_broadphase's bodies that meet every body: the world with geoms, and a
// static body with a plane or a height field, when they can collide.
bool MeetsEveryBody(const mjModel* m, int b) {
  if (!CanCollide(m, b)) return false;
  if (b == 0) return m->body_geomnum[0] > 0;
  if (m->body_weldid[b] != 0) return false;
  for (int g = m->body_geomadr[b]; g < m->body_geomadr[b] + m->body_geomnum[b]; ++g) {
    if (m->geom_type[g] == mjGEOM_PLANE || m->geom_type[g] == mjGEOM_HFIELD) return true;
  }
  return false;
}

}  // namespace

bool ProposedWhenNear(const mjModel* m, int g0, int g1) {
  if ((m->opt.disableflags & (mjDSBL_CONSTRAINT | mjDSBL_CONTACT)) || m->nconmax == 0 ||
      m->nbody < 2 || m->opt.collision == mjCOL_PAIR) {
    return false;
  }
  const int b0 = m->geom_bodyid[g0];
  const int b1 = m->geom_bodyid[g1];
  if (MeetsEveryBody(m, b0) || MeetsEveryBody(m, b1)) return true;
  // the sweep and prune: both bodies collidable, and two single-geom bodies
  // by their geoms' contype and conaffinity (add_pair)
  if (!CanCollide(m, b0) || !CanCollide(m, b1)) return false;
  if (m->body_geomnum[b0] == 1 && m->body_geomnum[b1] == 1) {
    const int a = m->body_geomadr[b0];
    const int b = m->body_geomadr[b1];
    return (m->geom_contype[a] & m->geom_conaffinity[b]) ||
           (m->geom_contype[b] & m->geom_conaffinity[a]);
  }
  return true;
}

StepPairs::StepPairs(const ContactModel& model)
    : model_(model), sweep_(std::make_unique<ReachSweep>(model.model())) {
  const mjModel* m = model.model();
  for (const GeomPair& pair : model.pairs()) {
    proposed_.push_back(ProposedWhenNear(m, pair.geom[0], pair.geom[1]));
  }
  reach_.assign(m->ngeom, 0.0);
  pairs_.reserve(model.pairs().size());
}

StepPairs::~StepPairs() = default;

const std::vector<int>& StepPairs::Find(const mjData* d, double h) {
  const mjModel* m = model_.model();
  const double fall = 0.5 * mju_norm3(m->opt.gravity) * h * h;
  for (int g = 0; g < m->ngeom; ++g) {
    const int body = m->geom_bodyid[g];
    mjtNum v[3];
    PointVelocity(model_, d, body, d->geom_xpos + 3 * g, v);
    const double spin = mju_norm3(d->cvel + 6 * body) * m->geom_rbound[g];
    reach_[g] = kStepReachFactor * ((mju_norm3(v) + spin) * h + fall);
  }
  pairs_.clear();
  sweep_->Overlaps(d, reach_, [&](int g0, int g1) {
    const int p = model_.FindPair(g0, g1);
    if (p >= 0 && proposed_[p]) pairs_.push_back(p);
  });
  std::sort(pairs_.begin(), pairs_.end());
  return pairs_;
}

}  // namespace contactlaws::internal
