// Copyright contactlaws authors.

#include "mujoco/friction_force.h"

#include <algorithm>
#include <cmath>

#include "contactlaws/friction.h"
#include "mujoco/kinematics.h"
#include "mujoco/vec3.h"

namespace contactlaws::internal {
namespace {

// v minus its component along the unit normal n.
void Project(const mjtNum n[3], mjtNum v[3]) {
  const mjtNum along = vec3::Dot(v, n);
  for (int i = 0; i < 3; ++i) v[i] -= along * n[i];
}

// The committed vector v rotated into the plane of the current normal n:
// projected, and rescaled to its size (its size is what the spring stores).
void ProjectKeepingSize(const mjtNum n[3], mjtNum v[3]) {
  const mjtNum size = vec3::Norm(v);
  Project(n, v);
  const mjtNum projected = vec3::Norm(v);
  if (projected > 0) vec3::Scale(v, v, size / projected);
}

// World position of a point given in body's frame.
void BodyPoint(const mjData* d, int body, const double local[3], mjtNum world[3]) {
  vec3::Rotate(world, local, d->xmat + 9 * body);
  vec3::AddTo(world, d->xpos + 3 * body);
}

// The rotation vector (world frame) of body since it had orientation q0.
void RotationSince(const mjData* d, int body, const double q0[4], mjtNum rotation[3]) {
  mjtNum inverse[4], dq[4];
  mju_negQuat(inverse, q0);
  mju_mulQuat(dq, d->xquat + 4 * body, inverse);
  mju_quat2Vel(rotation, dq, 1.0);
}

// The slip and spin of body[1] relative to body[0] at the contact point (the
// world and driven bodies do not turn), into e: e->slip holds body[1]'s
// velocity relative to body[0] there (PointEvaluator::EvaluatePoint), which
// becomes its part in the tangent plane.
void SlipAndSpin(const ContactModel& model, const mjData* d, const GeomPair& pair,
                 const mjContact& con, PointEvaluation* e) {
  const int b0 = pair.body[0];
  const int b1 = pair.body[1];
  Project(con.frame, e->slip);
  const mjtNum* w0 = model.FindDrive(b0) ? nullptr : d->cvel + 6 * b0;
  const mjtNum* w1 = model.FindDrive(b1) ? nullptr : d->cvel + 6 * b1;
  for (int i = 0; i < 3; ++i) e->spin[i] = (w1 ? w1[i] : 0.0) - (w0 ? w0[i] : 0.0);
}

// The rolling and torsional resistance of a point (condim 4 and 6) with the
// committed state c and tangential stiffness k: adds the torques to
// d->qfrc_passive and records them in *e.
void AddRollingResistance(const mjModel* m, mjData* d, const GeomPair& pair,
                          const FrictionState& c, double k, PointEvaluation* e) {
  const double* n = e->normal;
  const double fn = std::max(e->force, 0.0);
  // the relative rotation since the commit, split along the normal
  // (torsion) and in the plane (rolling); so are the rate and the state
  mjtNum r0[3] = {0, 0, 0}, r1[3] = {0, 0, 0};
  if (e->episode >= 0) {
    RotationSince(d, pair.body[0], c.orientation[0], r0);
    RotationSince(d, pair.body[1], c.orientation[1], r1);
  }
  mjtNum rotation[3];
  mju_sub3(rotation, r1, r0);
  const double lengths[2] = {pair.friction.torsional, pair.friction.rolling};
  for (int part = 0; part < 2; ++part) {
    if (!(lengths[part] > 0)) continue;
    CappedSpringInput in;
    mjtNum state[3];
    mju_copy3(state, c.torque);
    mju_copy3(in.stretch, rotation);
    mju_copy3(in.rate, e->spin);
    if (part == 0) {
      // along n
      mju_scl3(state, n, mju_dot3(state, n));
      mju_scl3(in.stretch, n, mju_dot3(in.stretch, n));
      mju_scl3(in.rate, n, mju_dot3(in.rate, n));
    } else {
      Project(n, state);
      ProjectKeepingSize(n, state);
      Project(n, in.stretch);
      Project(n, in.rate);
    }
    // k l^2: the tangential spring's stiffness over the lever l, so that
    // the cap l F_n is reached at the same stretch over l; critically
    // damped with the pair's moment of inertia
    const double l2 = lengths[part] * lengths[part];
    mju_copy3(in.committed, state);
    in.stiffness = k * l2;
    in.committed_stiffness = c.torque_stiffness[part];
    in.damping = 2 * std::sqrt(in.stiffness * pair.friction_inertia);
    in.stick_limit = in.slide_limit = lengths[part] * fn;
    in.was_sliding = c.torque_sliding[part];
    const CappedSpringOutput out = CappedSpring(in);
    AddTorque(m, d, pair.body[1], out.force, d->qfrc_passive);
    mjtNum opposite[3];
    mju_scl3(opposite, out.force, -1.0);
    AddTorque(m, d, pair.body[0], opposite, d->qfrc_passive);
    mju_addTo3(e->friction_torque, out.force);
    mju_addTo3(e->friction_state.torque, out.spring);
    e->friction_state.torque_stiffness[part] = in.stiffness;
    e->friction_state.torque_sliding[part] = out.sliding;
    e->friction_energy += out.stored_energy;
    e->friction_power -= mju_dot3(out.force, in.rate);
  }
}

// The memory of a point without an episode (its touch).
constexpr FrictionState kNoMemory{};

}  // namespace

void AddFriction(const ContactModel& model, mjData* d, const EpisodeLog& episodes,
                 const GeomPair& pair, const mjContact& con, PointEvaluation* e,
                 TangentialForce tangential) {
  const mjtNum* n = con.frame;
  const int b0 = pair.body[0];
  const int b1 = pair.body[1];
  SlipAndSpin(model, d, pair, con, e);
  const FrictionParams& params = pair.friction;
  if (params.kind == FrictionKind::kNone) return;

  // only what the model reads (regularized: the slip and the load), and
  // what rolling resistance reads (the committed orientations, k_t)
  const bool rolling = params.torsional > 0 || params.rolling > 0;
  const bool stick = ReadsStickState(params.kind);
  const bool spring = ReadsTangentialSpring(params.kind);

  // the committed state, turned into the current tangent plane, and the
  // stretch of the spring since: the anchors' relative displacement
  // (read in place: a point's memory is large, and this runs at every stage)
  const FrictionState& committed = e->episode >= 0 && (stick || rolling)
                                       ? episodes.CommittedFriction(e->episode)
                                       : kNoMemory;
  FrictionInput in;
  vec3::Copy(in.committed, committed.spring);
  if (e->episode >= 0 && stick) {
    const double(&anchors)[2][3] = episodes.Anchors(e->episode);
    mjtNum p0[3], p1[3];
    BodyPoint(d, b0, anchors[0], p0);
    BodyPoint(d, b1, anchors[1], p1);
    vec3::Sub(in.stretch, p1, p0);
    Project(n, in.stretch);
    ProjectKeepingSize(n, in.committed);
  }
  vec3::Copy(in.slip, e->slip);
  in.was_sliding = committed.sliding;
  in.normal_force = std::max(e->force, 0.0);

  // k_t: the tag's, or Mindlin's no-slip spring at this depth; c_t
  // (a weighted point's springs and dampers are its weight's share)
  const double stiffness =
      spring || rolling ? TangentialStiffness(params, pair.params, e->depth) : 0.0;
  in.stiffness = e->weight * stiffness;
  in.committed_stiffness = committed.stiffness;
  in.mass = pair.friction_mass;
  if (spring) {
    ContactState state;
    state.depth = e->depth;
    state.depth_rate = e->depth_rate;
    state.impact_velocity = e->impact_velocity;
    in.damping = e->weight * TangentialDamping(params, pair.params, state, stiffness,
                                               pair.friction_mass);
  }

  const FrictionOutput out = EvaluateFriction(params, in);
  for (int b = 0; tangential == TangentialForce::kAdd && b < 2; ++b) {
    mjtNum push[3];
    vec3::Scale(push, out.force, b == 1 ? 1.0 : -1.0);
    AddPointForce(model.model(), d, pair.body[b], con.pos, push, d->qfrc_passive);
  }
  vec3::Copy(e->friction, out.force);
  e->friction_energy = out.stored_energy;
  // the power friction takes from the bodies (the ledger: contact_memory.h)
  e->friction_power = -vec3::Dot(out.force, e->slip);
  FrictionState& next = e->friction_state;
  vec3::Copy(next.spring, out.state);
  next.sliding = out.sliding;
  next.stiffness = in.stiffness;
  for (int k = 0; k < 4; ++k) {
    next.orientation[0][k] = d->xquat[4 * b0 + k];
    next.orientation[1][k] = d->xquat[4 * b1 + k];
  }
  if (rolling) AddRollingResistance(model.model(), d, pair, committed, in.stiffness, e);
}

}  // namespace contactlaws::internal
