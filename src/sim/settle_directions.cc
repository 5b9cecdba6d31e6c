// Copyright contactlaws authors.

#include "sim/settle_directions.h"

#include <algorithm>
#include <cmath>

namespace contactlaws {
namespace {

// A normal whose part outside the span of the others is shorter than this
// lies in it (sin 0.06 degrees): the contacts of a box's face on a floor
// share one normal up to rounding.
constexpr double kIndependent = 1e-3;

}  // namespace

void SettleDirections::AddNormal(const mjModel* m, int b, const mjtNum normal[3]) {
  const int j = m->body_jntadr[b];
  if (m->body_jntnum[b] != 1 || m->jnt_type[j] != mjJNT_FREE) return;
  auto it = std::find_if(bodies_.begin(), bodies_.end(),
                         [&](const Body& body) { return body.body == b; });
  if (it == bodies_.end()) {
    bodies_.push_back(Body{});
    it = bodies_.end() - 1;
    it->body = b;
    it->joint = j;
  }
  // Gram-Schmidt: its part outside the basis, if long enough, joins it
  mjtNum rest[3];
  mju_copy3(rest, normal);
  for (int k = 0; k < it->rank; ++k) {
    mju_addToScl3(rest, it->basis[k], -mju_dot3(rest, it->basis[k]));
  }
  if (it->rank < 3 && mju_normalize3(rest) > kIndependent) {
    mju_copy3(it->basis[it->rank++], rest);
  }
}

void SettleDirections::Start(const mjModel* m, const mjData* d) {
  for (Body& body : bodies_) {
    const mjtNum* q = d->qpos + m->jnt_qposadr[body.joint];
    mju_copy3(body.pos0, q);
    mju_copy4(body.quat0, q + 3);
  }
}

const SettleDirections::Body* SettleDirections::Find(int b) const {
  for (const Body& body : bodies_) {
    if (body.body == b) return &body;
  }
  return nullptr;
}

bool SettleDirections::Held(int b) const { return Find(b) != nullptr; }

void SettleDirections::Translate(const Body& body, mjtNum v[3]) {
  mjtNum along[3] = {0, 0, 0};
  for (int k = 0; k < body.rank; ++k) {
    mju_addToScl3(along, body.basis[k], mju_dot3(v, body.basis[k]));
  }
  mju_copy3(v, along);
}

void SettleDirections::Project(const mjModel* m, mjData* d) const {
  for (const Body& body : bodies_) {
    mjtNum* q = d->qpos + m->jnt_qposadr[body.joint];
    mjtNum* v = d->qvel + m->jnt_dofadr[body.joint];
    // the position: the start's, moved along the normals only
    mjtNum offset[3];
    mju_sub3(offset, q, body.pos0);
    Translate(body, offset);
    mju_add3(q, body.pos0, offset);
    Translate(body, v);
    if (body.rank != 1) continue;
    // one normal n: the turn since the start (world frame) without its part
    // about n, and the angular velocity (local frame) likewise
    const mjtNum* n = body.basis[0];
    mjtNum inverse0[4], turn[4], axis[3];
    mju_negQuat(inverse0, body.quat0);
    mju_normalize4(q + 3);
    mju_mulQuat(turn, q + 3, inverse0);
    mju_quat2Vel(axis, turn, 1.0);
    mju_addToScl3(axis, n, -mju_dot3(axis, n));
    const mjtNum angle = mju_normalize3(axis);
    mju_axisAngle2Quat(turn, axis, angle);
    mju_mulQuat(q + 3, turn, body.quat0);
    mjtNum world[3], inverse[4];
    mju_rotVecQuat(world, v + 3, q + 3);
    mju_addToScl3(world, n, -mju_dot3(world, n));
    mju_negQuat(inverse, q + 3);
    mju_rotVecQuat(v + 3, world, inverse);
  }
}

SettleDirections::Acceleration SettleDirections::Residual(const mjModel* m, const mjData* d,
                                                          int b) const {
  const Body* body = Find(b);
  const mjtNum* a = d->qacc + m->jnt_dofadr[body->joint];
  mjtNum linear[3], angular[3];
  mju_copy3(linear, a);
  Translate(*body, linear);
  mju_rotVecQuat(angular, a + 3, d->qpos + m->jnt_qposadr[body->joint] + 3);
  if (body->rank == 1) mju_addToScl3(angular, body->basis[0], -mju_dot3(angular, body->basis[0]));
  Acceleration residual;
  for (int i = 0; i < 3; ++i) {
    residual.linear = std::max(residual.linear, std::abs(linear[i]));
    residual.angular = std::max(residual.angular, std::abs(angular[i]));
  }
  return residual;
}

void SettleDirections::Load(const mjModel* m, const mjData* d, int b, mjtNum f[3]) {
  const int dof = m->jnt_dofadr[m->body_jntadr[b]];
  mju_scl3(f, m->opt.gravity, m->body_subtreemass[b]);
  mju_addTo3(f, d->qfrc_actuator + dof);
  mju_addTo3(f, d->qfrc_applied + dof);
  mju_addTo3(f, d->xfrc_applied + 6 * b);
}

void SettleDirections::Tangential(const mjModel* m, const mjData* d, int b, mjtNum t[3]) const {
  mju_zero3(t);
  const Body* body = Find(b);
  if (!body) return;
  mjtNum along[3];
  Load(m, d, b, t);
  mju_copy3(along, t);
  Translate(*body, along);
  mju_subFrom3(t, along);
}

void SettleDirections::CancelAlongSurfaces(const mjModel* m, mjData* d) const {
  for (const Body& body : bodies_) {
    mjtNum* applied = d->qfrc_applied + m->jnt_dofadr[body.joint];
    mjtNum tangential[3];
    Tangential(m, d, body.body, tangential);
    mju_subFrom3(applied, tangential);
    if (body.rank != 1) continue;
    // the torque about the one normal (local frame in qfrc, world here)
    const mjtNum* quat = d->qpos + m->jnt_qposadr[body.joint] + 3;
    const mjtNum* n = body.basis[0];
    mjtNum local[3], world[3], inverse[4];
    mju_add3(local, d->qfrc_actuator + m->jnt_dofadr[body.joint] + 3, applied + 3);
    mju_rotVecQuat(world, local, quat);
    mju_scl3(world, n, mju_dot3(world, n) + mju_dot3(d->xfrc_applied + 6 * body.body + 3, n));
    mju_negQuat(inverse, quat);
    mju_rotVecQuat(local, world, inverse);
    mju_subFrom3(applied + 3, local);
  }
}

double SettleDirections::Carried(int b, const mjtNum f[3]) const {
  const Body* body = Find(b);
  const mjtNum norm = mju_norm3(f);
  if (!body || norm == 0) return 1.0;
  mjtNum along[3];
  mju_copy3(along, f);
  Translate(*body, along);
  return mju_norm3(along) / norm;
}

}  // namespace contactlaws
