// Copyright contactlaws authors.

#include "sim/dense_rows.h"

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
  if (end_.time == sim_->time()) {
    std::swap(start_, end_);
  } else {
    Capture(&start_);
  }
}

void DenseRows::End() { Capture(&end_); }

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
  // coordinates from qpos and qvel, joint by joint
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
    mjtNum inverse[4], relative[4], delta[3], end_rate[3], phi[3];
    mju_negQuat(inverse, a.qpos.data() + rotation);
    mju_mulQuat(relative, inverse, b.qpos.data() + rotation);
    mju_quat2Vel(delta, relative, 1.0);
    mju_rotVecQuat(end_rate, b.qvel.data() + w, relative);
    for (int k = 0; k < 3; ++k) {
      phi[k] = Hermite(s, 0.0, h * a.qvel[w + k], delta[k], h * end_rate[k]);
    }
    mjtNum* quat = d->qpos + rotation;
    mju_copy4(quat, a.qpos.data() + rotation);
    mju_quatIntegrate(quat, phi, 1.0);
    mju_normalize4(quat);
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
