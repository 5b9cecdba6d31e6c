// Copyright contactlaws authors.

#include "sim/settle_friction.h"

#include <algorithm>

#include "contactlaws/friction.h"

namespace contactlaws {
namespace {

// The normal force of point e on body b (world, N): e.normal points from
// its pair's body[0] to body[1].
void NormalForceOn(const GeomPair& pair, const PointEvaluation& e, int b, mjtNum f[3]) {
  mju_scl3(f, e.normal, b == pair.body[1] ? e.force : -e.force);
}

}  // namespace

std::vector<PointEvaluation> HeldFriction(const Simulation& sim) {
  std::vector<PointEvaluation> points = sim.contacts().latest();
  for (PointEvaluation& e : points) {
    e.depth_rate = e.max_approach = e.touch_velocity = 0;
    e.impact_velocity = sim.contact_model().pairs()[e.pair].params.min_impact_velocity;
  }
  return points;
}

std::vector<PointEvaluation> StartFriction(const Simulation& sim,
                                           const SettleDirections& directions, bool* sliding) {
  const mjModel* m = sim.model();
  const mjData* d = sim.data();
  const std::vector<GeomPair>& pairs = sim.contact_model().pairs();
  std::vector<PointEvaluation> points = HeldFriction(sim);
  for (PointEvaluation& e : points) {
    e.friction_state.spring[0] = e.friction_state.spring[1] = e.friction_state.spring[2] = 0;
    e.friction_state.sliding = false;
  }
  *sliding = false;

  // the held bodies, highest first; what each passes down to the others
  std::vector<int> bodies;
  for (int b = 1; b < m->nbody; ++b) {
    if (directions.Held(b)) bodies.push_back(b);
  }
  auto height = [&](int b) { return -mju_dot3(d->xipos + 3 * b, m->opt.gravity); };
  std::stable_sort(bodies.begin(), bodies.end(),
                   [&](int a, int b) { return height(a) > height(b); });
  std::vector<mjtNum> passed(3 * m->nbody, 0.0);

  for (const int b : bodies) {
    mjtNum load[3], tangential[3];
    SettleDirections::Load(m, d, b, load);
    directions.Tangential(m, d, b, tangential);
    mju_addTo3(tangential, passed.data() + 3 * b);
    // its supporting points with a stick spring, and their capacity
    std::vector<PointEvaluation*> support;
    double normal = 0, capacity = 0;
    for (PointEvaluation& e : points) {
      const GeomPair& pair = pairs[e.pair];
      if (pair.body[0] != b && pair.body[1] != b) continue;
      if (!ReadsTangentialSpring(pair.friction.kind)) continue;
      mjtNum push[3];
      NormalForceOn(pair, e, b, push);
      if (mju_dot3(push, load) >= 0 || e.force <= 0) continue;
      support.push_back(&e);
      normal += e.force;
      capacity += pair.friction.mu_static * e.force;
    }
    const double size = mju_norm3(tangential);
    if (support.empty() || size == 0) continue;
    const bool slides = size > capacity;
    *sliding = *sliding || slides;
    for (PointEvaluation* e : support) {
      const GeomPair& pair = pairs[e->pair];
      // the friction on b, in the point's tangent plane
      mjtNum friction[3];
      mju_scl3(friction, tangential,
               slides ? -pair.friction.mu_kinetic * e->force / size : -e->force / normal);
      mju_addToScl3(friction, e->normal, -mju_dot3(friction, e->normal));
      // the spring's force on body[1]; the other body takes the reaction
      const int other = pair.body[0] == b ? pair.body[1] : pair.body[0];
      mju_scl3(e->friction_state.spring, friction, pair.body[1] == b ? 1.0 : -1.0);
      e->friction_state.sliding = slides;
      mju_subFrom3(passed.data() + 3 * other, friction);
    }
  }
  return points;
}

}  // namespace contactlaws
