// Copyright contactlaws authors.

#include "sim/dense_rows.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "memory/contact_memory.h"
#include "mujoco/kinematics.h"
#include "contactlaws/contact_model.h"

namespace contactlaws {
namespace {

// The cubic Hermite at s in [0, 1] through values y0, y1 with derivatives
// (already times the interval) m0, m1.
double Hermite(double s, double y0, double m0, double y1, double m1) {
  const double s2 = s * s;
  const double s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * y1 +
         (s3 - s2) * m1;
}

// q = q0 exp(phi): q0 turned by the rotation vector phi (q0's frame), to
// rounding of q0's length; the kinematics that read q normalize it
// (mj_kinematics and FreeBodyKinematics normalize qpos's quaternions in place).
void Rotated(const mjtNum q0[4], const mjtNum phi[3], mjtNum q[4]) {
  const double squared = phi[0] * phi[0] + phi[1] * phi[1] + phi[2] * phi[2];
  if (squared == 0) {  // no turn (a body that does not spin): q0 itself
    std::copy(q0, q0 + 4, q);
    return;
  }
  const double angle = std::sqrt(squared);
  // sin(angle / 2) / angle, by its series below 1e-4 rad, where the series'
  // next term (angle^4 / 3840) is below 2.6e-20, far under an ulp of 1/2
  const double scale =
      angle < 1e-4 ? 0.5 - angle * angle / 48 : std::sin(0.5 * angle) / angle;
  const mjtNum r[4] = {std::cos(0.5 * angle), scale * phi[0], scale * phi[1], scale * phi[2]};
  mju_mulQuat(q, q0, r);
}

// The rotation of a step as the angular velocities turn it: q0^-1 q1 gives
// its angle modulo a whole turn (mju_quat2Vel's in (-pi, pi]), and a step of
// free flight can turn a body further (a die spinning at 10 rad/s through a
// 0.4 s flight). Of the angles that q1 allows, the one nearest the trapezoid
// of the ends' angular velocities (q0's frame) over the step, h (w0 + w1) / 2;
// the same delta whenever that is within half a turn of it.
void Unwrap(double h, const mjtNum w0[3], const mjtNum w1[3], mjtNum delta[3]) {
  constexpr double kTurn = 2 * mjPI;
  mjtNum predicted[3];
  for (int k = 0; k < 3; ++k) predicted[k] = 0.5 * h * (w0[k] + w1[k]);
  double angle = std::sqrt(delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2]);
  mjtNum axis[3];
  if (angle > 0) {
    for (int k = 0; k < 3; ++k) axis[k] = delta[k] / angle;
  } else {
    // q1 = +-q0: no axis of its own; the velocities' (whole turns about it)
    const double turned = std::sqrt(predicted[0] * predicted[0] + predicted[1] * predicted[1] +
                                    predicted[2] * predicted[2]);
    if (turned < 0.5 * kTurn) return;
    for (int k = 0; k < 3; ++k) axis[k] = predicted[k] / turned;
  }
  const double along = axis[0] * predicted[0] + axis[1] * predicted[1] + axis[2] * predicted[2];
  const double turns = std::round((along - angle) / kTurn);
  if (turns == 0) return;
  angle += turns * kTurn;
  for (int k = 0; k < 3; ++k) delta[k] = angle * axis[k];
}

}  // namespace

DenseRows::DenseRows(Simulation* sim)
    : sim_(sim), free_bodies_(OnlySingleFreeBodies(sim->model())) {
  scratch_.reset(mj_makeData(sim->model()));
  if (!scratch_) throw Error(fmt::format("{}: MuJoCo could not allocate mjData", sim->source()));
}

void DenseRows::Capture(State* state) {
  const mjModel* m = sim_->model();
  mjData* d = sim_->data();
  const PositionsKept kept(m, d, &kept_positions_);
  mj_forward(m, d);
  state->time = d->time;
  state->qpos.assign(d->qpos, d->qpos + m->nq);
  state->qvel.assign(d->qvel, d->qvel + m->nv);
  state->qacc.assign(d->qacc, d->qacc + m->nv);
  state->readings = sim_->Readings();
  state->dissipated = sim_->contacts().DissipatedEnergy();
  // the laws' springs and their power (force - damping) d' = elastic d',
  // the friction springs, and the power the ledger's total takes in
  const std::vector<PointEvaluation>& points = sim_->contacts().latest();
  state->spring = state->spring_rate = state->friction_spring = 0;
  for (const PointEvaluation& e : points) {
    state->spring += sim_->contacts().LawEnergy(e);
    state->spring_rate += e.force * e.depth_rate - e.dissipated_power;
    state->friction_spring += e.friction_energy;
  }
  state->dissipated_power = DissipatedPower(points);
}

void DenseRows::Start() {
  turns_current_ = false;
  if (end_.time == sim_->time()) {
    std::swap(start_, end_);
  } else {
    Capture(&start_);
  }
}

void DenseRows::End() {
  Capture(&end_);
  turns_current_ = false;
}

void DenseRows::Row(double t, double tolerance, std::vector<double>* row) {
  if (std::abs(t - end_.time) <= tolerance || !(start_.time < end_.time)) {
    sim_->Row(sim_->data(), end_.readings, end_.spring + end_.friction_spring, end_.dissipated,
              row);
    return;
  }
  Interpolate(t);
  const State& a = start_;
  const State& b = end_;
  const double h = b.time - a.time;
  const double s = (t - a.time) / h;
  auto line = [s](double y0, double y1) { return y0 + s * (y1 - y0); };
  readings_.resize(b.readings.size());
  for (size_t i = 0; i < readings_.size(); ++i) {
    const TagReading& ra = a.readings[i];
    const TagReading& rb = b.readings[i];
    // a depth in contact at both ends follows its rate
    readings_[i].depth = ra.depth > 0 && rb.depth > 0
                             ? Hermite(s, ra.depth, h * ra.depth_rate, rb.depth, h * rb.depth_rate)
                             : line(ra.depth, rb.depth);
    readings_[i].depth_rate = line(ra.depth_rate, rb.depth_rate);
    readings_[i].force = line(ra.force, rb.force);
    for (int k = 0; k < 3; ++k) readings_[i].friction[k] = line(ra.friction[k], rb.friction[k]);
  }
  // the springs' energy and the dissipated energy follow their powers; the
  // friction springs' (and their share of the dissipated) the chord
  const double friction_spring = line(a.friction_spring, b.friction_spring);
  const double friction_rate = (b.friction_spring - a.friction_spring) / h;
  const double spring = Hermite(s, a.spring, h * a.spring_rate, b.spring, h * b.spring_rate);
  const double dissipated =
      Hermite(s, a.dissipated, h * (a.dissipated_power - friction_rate), b.dissipated,
              h * (b.dissipated_power - friction_rate));
  sim_->Row(scratch_.get(), readings_, spring + friction_spring, dissipated, row, kinetic_);
}

void DenseRows::Turns() {
  const mjModel* m = sim_->model();
  turns_.clear();
  for (int j = 0; j < m->njnt; ++j) {
    const mjtJoint type = static_cast<mjtJoint>(m->jnt_type[j]);
    if (type != mjJNT_FREE && type != mjJNT_BALL) continue;
    const int rotation = m->jnt_qposadr[j] + (type == mjJNT_FREE ? 3 : 0);
    const int w = m->jnt_dofadr[j] + (type == mjJNT_FREE ? 3 : 0);
    mjtNum inverse[4], relative[4], delta[3], end_rate[3];
    mju_negQuat(inverse, start_.qpos.data() + rotation);
    mju_mulQuat(relative, inverse, end_.qpos.data() + rotation);
    mju_quat2Vel(delta, relative, 1.0);
    mju_rotVecQuat(end_rate, end_.qvel.data() + w, relative);
    Unwrap(end_.time - start_.time, start_.qvel.data() + w, end_rate, delta);
    turns_.insert(turns_.end(), delta, delta + 3);
    turns_.insert(turns_.end(), end_rate, end_rate + 3);
  }
  turns_current_ = true;
}

void DenseRows::Interpolate(double t) {
  const mjModel* m = sim_->model();
  mjData* d = scratch_.get();
  const double h = end_.time - start_.time;
  const double s = (t - start_.time) / h;
  const State& a = start_;
  const State& b = end_;
  // every dof's velocity from qvel and qacc
  for (int v = 0; v < m->nv; ++v) {
    d->qvel[v] = Hermite(s, a.qvel[v], h * a.qacc[v], b.qvel[v], h * b.qacc[v]);
  }
  if (!turns_current_) Turns();
  // coordinates from qpos and qvel, joint by joint
  int turn = 0;  // the rotation's index in turns_
  for (int j = 0; j < m->njnt; ++j) {
    const int q = m->jnt_qposadr[j];
    const int v = m->jnt_dofadr[j];
    int rotation = -1;  // qpos address of a quaternion, its dofs at v + 3 or v
    switch (m->jnt_type[j]) {
      case mjJNT_FREE:
        for (int k = 0; k < 3; ++k) {
          d->qpos[q + k] =
              Hermite(s, a.qpos[q + k], h * a.qvel[v + k], b.qpos[q + k], h * b.qvel[v + k]);
        }
        rotation = q + 3;
        break;
      case mjJNT_BALL:
        rotation = q;
        break;
      default:
        d->qpos[q] = Hermite(s, a.qpos[q], h * a.qvel[v], b.qpos[q], h * b.qvel[v]);
    }
    if (rotation < 0) continue;
    const int w = m->jnt_type[j] == mjJNT_FREE ? v + 3 : v;
    // phi: rotation vectors in q0's frame; angular velocities are local
    const mjtNum* delta = turns_.data() + 6 * turn;
    const mjtNum* end_rate = delta + 3;
    ++turn;
    mjtNum phi[3];
    for (int k = 0; k < 3; ++k) {
      phi[k] = Hermite(s, 0.0, h * a.qvel[w + k], delta[k], h * end_rate[k]);
    }
    Rotated(a.qpos.data() + rotation, phi, d->qpos + rotation);
  }
  // driven bodies at their prescribed pose, then the kinematics the row reads
  d->time = t;
  for (const Drive& drive : sim_->contact_model().drives()) {
    drive.Position(t, d->mocap_pos + 3 * drive.mocap);
  }
  if (free_bodies_) {
    kinetic_ = FreeBodyKinematics(m, d);
    return;
  }
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_comVel(m, d);
  mj_crb(m, d);
}

}  // namespace contactlaws
