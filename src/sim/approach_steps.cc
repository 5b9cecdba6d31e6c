// Copyright contactlaws authors.

#include "sim/approach_steps.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/estimate.h"
#include "mujoco/kinematics.h"
#include "mujoco/hooks.h"
#include "scene/model_queries.h"
#include "mujoco/reach_sweep.h"

namespace contactlaws {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The step that reaches a predicted touch ends this fraction of a fine step
// past it, in contact, whatever the rounding of the prediction.
constexpr double kTouchOvershoot = 1e-3;

// The top acceleration of the driven bodies among body, m/s^2 (A w^2 each).
double DriveAcceleration(const ContactModel& cm, const std::array<int, 2>& body) {
  double accel = 0;
  for (int b : body) {
    if (const Drive* drive = cm.FindDrive(b)) {
      accel += std::abs(drive->amplitude) * drive->omega * drive->omega;
    }
  }
  return accel;
}

// The radius at which spin moves geom g's surface towards another geom's, m:
// its bounding radius, but 0 for a sphere, whose surface turns within itself
// (spin neither closes its gap nor adds to its impact speed).
double SpinRadius(const mjModel* m, int g) {
  return m->geom_type[g] == mjGEOM_SPHERE ? 0.0 : m->geom_rbound[g];
}

}  // namespace

double TimeToClose(double g, double v, double a) {
  if (a > 0) {
    // the positive root of a h^2 / 2 + v h = g; closing (v > 0) in the form
    // without cancellation: -v + sqrt(v^2 + 2 a g) is 0 in doubles once
    // 2 a g < v^2 1e-16 (gravity's rounding along a wall's normal, 2e-15
    // m/s^2, made every ball beside a wall "touching now")
    const double root = std::sqrt(v * v + 2 * a * g);
    return v > 0 ? 2 * g / (v + root) : (root - v) / a;
  }
  if (v > 0) return g / v;
  return kInfinity;
}

ApproachSteps::ApproachSteps(const ContactData& contacts, double gap_fraction)
    : contacts_(contacts),
      gap_fraction_(gap_fraction),
      sweep_(std::make_unique<internal::ReachSweep>(contacts.model().model())) {
  const ContactModel& cm = contacts.model();
  for (const GeomPair& pair : cm.pairs()) {
    top_acceleration_.push_back(DriveAcceleration(cm, pair.body));
  }
  has_untagged_ = HasUntaggedContacts(cm);
  scene_step_ = cm.model()->opt.timestep;
  reach_.assign(cm.model()->ngeom, kInfinity);
}

ApproachSteps::~ApproachSteps() = default;
ApproachSteps::ApproachSteps(ApproachSteps&&) noexcept = default;

void ApproachSteps::Step(const mjData* d, double reach_bound,
                         const std::vector<uint8_t>& in_contact, const PairSteps& pair_steps,
                         StepBound* bound, bool* fine) {
  const ContactModel& cm = contacts_.model();
  const mjModel* m = cm.model();
  // only the pairs that could close within reach_bound can shorten the
  // step: those whose geoms' reaches overlap
  SetReach(reach_bound);
  sweep_->Overlaps(d, reach_, [&](int g0, int g1) {
    const int p = cm.FindPair(g0, g1);
    if (p >= 0) {
      if (!in_contact[p]) PairStep(p, pair_steps, bound, fine);
    } else if (!DefaultContactFilter(m, g0, g1)) {
      // untagged: the scene's step while MuJoCo's contact can reach it
      bound->Limit(UntaggedStep(g0, g1, std::max(m->geom_margin[g0], m->geom_margin[g1])));
    }
  });
  for (int i = 0; i < m->npair; ++i) {
    bound->Limit(UntaggedStep(m->pair_geom1[i], m->pair_geom2[i], m->pair_margin[i]));
  }
}

bool ApproachSteps::Closes(const std::array<int, 2>& g, const std::array<int, 2>& body,
                          double top_acceleration, Closing* c) const {
  const ContactModel& cm = contacts_.model();
  const mjModel* m = cm.model();
  const mjData* d = contacts_.data();
  const double rb[2] = {m->geom_rbound[g[0]], m->geom_rbound[g[1]]};
  mjtNum normal[3];  // from geom[0] towards geom[1]
  if (!BoundingGap(m, d, g[0], g[1], &c->gap, normal)) {
    return false;  // no bounding sphere (planes, height fields)
  }
  double spin = 0;   // what rotation adds to the closing speed
  if (rb[0] > 0 && rb[1] > 0) {
    for (int b = 0; b < 2; ++b) {
      if (!cm.FindDrive(body[b])) spin += mju_norm3(d->cvel + 6 * body[b]) * SpinRadius(m, g[b]);
    }
  } else {
    // a plane and the other geom's sphere
    const int b = rb[0] > 0 ? 0 : 1;
    spin = mju_norm3(d->cvel + 6 * body[b]) * SpinRadius(m, g[b]);
  }
  mjtNum v[2][3], relative[3];
  for (int b = 0; b < 2; ++b) contacts_.PointVelocity(body[b], d->geom_xpos + 3 * g[b], v[b]);
  mju_sub3(relative, v[0], v[1]);
  c->speed = mju_dot3(relative, normal) + spin;
  c->accel = top_acceleration + GravityClosingAcceleration(cm, body, normal);
  return true;
}

void ApproachSteps::PairStep(int p, const PairSteps& pair_steps, StepBound* bound,
                             bool* fine) const {
  const GeomPair& pair = contacts_.model().pairs()[p];
  Closing c;
  if (!Closes(pair.geom, pair.body, top_acceleration_[p], &c)) {
    // always near
    *fine = true;
    bound->Limit(pair_steps.Fine(p, 0.0));
    return;
  }
  const double gap = c.gap;
  const double closing = c.speed;
  const double accel = c.accel;
  const double pair_fine = pair_steps.Fine(p, SpeedAtTouch(closing, accel, gap));
  const double allowed =
      gap > 0 ? TimeToClose(gap_fraction_ * gap, closing, accel) : 0.0;
  if (allowed > pair_fine) {
    bound->Limit(allowed);
    return;
  }
  // near: fine steps, and the ones that reach the touch end just before and
  // just past it,
  // so that a force that jumps at d = 0+ acts from the start of a step (a
  // touch within a step would act for a fraction of it: an error of the
  // first order in the step)
  *fine = true;
  // bounding spheres that overlap out of contact: no touch to predict
  if (!(gap > 0)) {
    bound->Limit(pair_fine);
    return;
  }
  const double touch = TimeToClose(gap, closing, accel);
  // first to just before the touch (the impact speed is read there, before
  // any force), then across it
  const double lead = kTouchOvershoot * pair_fine;
  bound->Land(touch > 2 * lead ? touch - lead : touch + lead, pair_fine);
}

double ApproachSteps::UntaggedStep(int g0, int g1, double margin) const {
  const mjModel* m = contacts_.model().model();
  const std::array<int, 2> g = CollisionOrder(m, g0, g1);  // a plane first, as GeomPair
  const std::array<int, 2> body = {m->geom_bodyid[g[0]], m->geom_bodyid[g[1]]};
  // both welded to the world: their gap never closes
  if (m->body_weldid[body[0]] == 0 && m->body_weldid[body[1]] == 0) return kInfinity;
  Closing c;
  // MuJoCo's contact starts at its margin; a pair within reach (or without
  // bounding spheres) needs the scene's own step
  if (!Closes(g, body, DriveAcceleration(contacts_.model(), body), &c) ||
      !(c.gap > margin)) {
    return scene_step_;
  }
  const double allowed = TimeToClose(gap_fraction_ * (c.gap - margin), c.speed, c.accel);
  return std::max(scene_step_, allowed);
}

void ApproachSteps::SetReach(double bound) {
  const ContactModel& cm = contacts_.model();
  const mjModel* m = cm.model();
  const mjData* d = contacts_.data();
  const double gravity = mju_norm3(m->opt.gravity);
  for (int g = 0; g < m->ngeom; ++g) {
    if (!std::isfinite(bound)) {
      reach_[g] = kInfinity;
      continue;
    }
    // what the geom's surface can move towards another's within bound: its
    // centre's speed, what spin adds, gravity and a drive's acceleration (a
    // pair closes at most at the sum of its geoms'), over gap_fraction,
    // twice for rounding, beyond MuJoCo's margin
    const int body = m->geom_bodyid[g];
    mjtNum v[3];
    contacts_.PointVelocity(body, d->geom_xpos + 3 * g, v);
    double speed = mju_norm3(v);
    if (!cm.FindDrive(body)) speed += mju_norm3(d->cvel + 6 * body) * SpinRadius(m, g);
    double accel = DriveAcceleration(cm, {body, body}) / 2;
    if (!Immovable(cm, body)) accel += gravity;
    const double travel = speed * bound + 0.5 * accel * bound * bound;
    reach_[g] = m->geom_margin[g] + 2 * travel / gap_fraction_;
  }
}

}  // namespace contactlaws
