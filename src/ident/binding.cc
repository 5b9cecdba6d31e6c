// Copyright contactlaws authors.

#include "ident/binding.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string_view>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"

namespace contactlaws::internal {

namespace {

// The quantity's index in list, -1 when absent.
template <size_t N>
int IndexOf(const char* const (&list)[N], std::string_view quantity) {
  for (size_t i = 0; i < N; ++i) {
    if (quantity == list[i]) return static_cast<int>(i);
  }
  return -1;
}

std::string QuantityList(const char* const* list, size_t n) {
  std::string text;
  for (size_t i = 0; i < n; ++i) text += (i ? " " : "") + std::string(list[i]);
  return text;
}

// v_body = R(q)^T v_world.
void RotateBack(const double q[4], const double v[3], double out[3]) {
  double conj[4];
  mju_negQuat(conj, q);
  mju_rotVecQuat(out, v, conj);
}

// The constant body-frame angular velocity that turns q0 into q1 in dt.
void AngularVelocity(const double q0[4], const double q1[4], double dt, double w[3]) {
  double conj[4], dq[4];
  mju_negQuat(conj, q0);
  mju_mulQuat(dq, conj, q1);
  mju_quat2Vel(w, dq, dt);
}

}  // namespace

Binding::Binding(const Scene& scene, const MeasuredData& data) : data_(data) {
  const mjModel* m = scene.model();
  auto fail = [&](const std::string& what) {
    throw Error(fmt::format("{}: {}", data.source, what));
  };
  for (size_t c = 0; c < data.columns.size(); ++c) {
    const std::string& column = data.columns[c];
    const size_t dot = column.rfind('.');
    const std::string name = column.substr(0, dot);
    const std::string_view quantity = std::string_view(column).substr(dot + 1);
    if (const int b = mj_name2id(m, mjOBJ_BODY, name.c_str()); b > 0) {
      const int q = IndexOf(kBodyQuantities, quantity);
      if (q < 0) {
        fail(fmt::format("column '{}': a body's quantities are {}", column,
                         QuantityList(kBodyQuantities, std::size(kBodyQuantities))));
      }
      auto it = std::find_if(bodies_.begin(), bodies_.end(),
                             [&](const MeasuredBody& x) { return x.body == b; });
      if (it == bodies_.end()) {
        MeasuredBody body;
        body.body = b;
        std::fill(std::begin(body.col), std::end(body.col), -1);
        bodies_.push_back(body);
        it = bodies_.end() - 1;
      }
      it->col[q] = static_cast<int>(c);
    } else if (const int j = mj_name2id(m, mjOBJ_JOINT, name.c_str()); j >= 0) {
      const int type = m->jnt_type[j];
      if (type != mjJNT_HINGE && type != mjJNT_SLIDE) {
        fail(fmt::format("column '{}': joint '{}' is a {} joint: measure its body's columns "
                         "(<body>.x ... .qw ...) instead",
                         column, name, type == mjJNT_FREE ? "free" : "ball"));
      }
      const int q = IndexOf(kJointQuantities, quantity);
      if (q < 0) fail(fmt::format("column '{}': a joint's quantities are q v", column));
      auto it = std::find_if(joints_.begin(), joints_.end(),
                             [&](const MeasuredJoint& x) { return x.joint == j; });
      if (it == joints_.end()) {
        MeasuredJoint joint;
        joint.joint = j;
        joint.qpos = m->jnt_qposadr[j];
        joint.qvel = m->jnt_dofadr[j];
        joints_.push_back(joint);
        it = joints_.end() - 1;
      }
      (q == 0 ? it->col_q : it->col_v) = static_cast<int>(c);
    } else {
      fail(fmt::format("column '{}': the scene {} has no body or joint '{}'", column,
                       scene.path(), name));
    }
  }
  // whole groups, and a free joint to set
  for (MeasuredBody& body : bodies_) {
    const std::string name = ObjectName(m, mjOBJ_BODY, body.body);
    const int groups[4][2] = {{kX, 3}, {kQw, 4}, {kVx, 3}, {kWx, 3}};
    for (const auto& g : groups) {
      int given = 0;
      for (int i = 0; i < g[1]; ++i) given += body.has(g[0] + i);
      for (int i = 0; given > 0 && i < g[1]; ++i) {
        if (!body.has(g[0] + i)) {
          fail(fmt::format("missing column {}.{} (beside {}.{})", name, kBodyQuantities[g[0] + i],
                           name, kBodyQuantities[g[0] + (i == 0 ? 1 : 0)]));
        }
      }
    }
    const int j = m->body_jntadr[body.body];
    body.free = m->body_jntnum[body.body] == 1 && m->jnt_type[j] == mjJNT_FREE;
    if (!body.has(kX) || (body.free && !body.has(kQw))) {
      fail(fmt::format("missing column {}.{}: {}", name, body.has(kX) ? "qw" : "x",
                       body.free ? "a free body's state needs its position (x y z) and "
                                   "orientation (qw qx qy qz)"
                                 : "a body is scored by its position (x y z)"));
    }
    if (body.free) {
      body.qpos = m->jnt_qposadr[j];
      body.qvel = m->jnt_dofadr[j];
    }
    body.length = std::numeric_limits<double>::infinity();
    for (int g = m->body_geomadr[body.body];
         g < m->body_geomadr[body.body] + m->body_geomnum[body.body]; ++g) {
      body.length = std::min(body.length, GeomSize(m, g));
      body.rbound = std::max(body.rbound, m->geom_rbound[g] + mju_norm3(m->geom_pos + 3 * g));
    }
    if (!std::isfinite(body.length)) body.length = 1.0;
  }
  for (const MeasuredJoint& joint : joints_) {
    if (joint.col_q < 0) {
      fail(fmt::format("missing column {}.q (beside {}.v)", ObjectName(m, mjOBJ_JOINT, joint.joint),
                       ObjectName(m, mjOBJ_JOINT, joint.joint)));
    }
  }
}

int Binding::StartSample(int i, const ReplayOptions& options) const {
  if (options.start == StartRule::kFirst) return 0;
  const auto free = std::find_if(bodies_.begin(), bodies_.end(), [](const MeasuredBody& b) { return b.free; });
  if (free == bodies_.end()) {
    throw OptionError(fmt::format("{}: {} needs a measured body with a free joint",
                                  data_.source, OptionError::kMark),
                      {{OptionError::Form::kGiven, "start", "refit"}});
  }
  const MeasuredBody& body = *free;
  const MeasuredTrajectory& t = data_.trajectories[i];
  const int width = static_cast<int>(data_.columns.size());
  const double height = options.refit.height.value_or(body.rbound);
  int first = t.samples() - 1;
  for (int k = 0; k < t.samples(); ++k) {
    if (t.values[k * width + body.col[kX + 2]] <= height) {
      first = k;
      break;
    }
  }
  return std::max(0, first - options.refit.lead);
}

void Binding::SetStart(const MeasuredTrajectory& t, int s, const ReplayOptions& options,
                       const mjModel* m, mjData* d) const {
  const bool refit = options.start == StartRule::kRefit && s >= options.refit.min_samples;
  const int next = s + 1 < t.samples() ? s + 1 : s;  // finite differences forward,
  const int prev = next == s ? s - 1 : s;            // or backward at the end
  const double dt = t.time[next] - t.time[prev];
  for (const MeasuredBody& b : bodies_) {
    if (!b.free) continue;  // set by its joints
    double* qpos = d->qpos + b.qpos;
    double* qvel = d->qvel + b.qvel;
    const double* x = Sample(t, s);
    for (int i = 0; i < 3; ++i) qpos[i] = x[b.col[kX + i]];
    for (int i = 0; i < 4; ++i) qpos[3 + i] = x[b.col[kQw + i]];
    mju_normalize4(qpos + 3);
    if (refit) {
      RefitVelocity(t, s, b, m->opt.gravity, qvel);
      continue;
    }
    const double* a = Sample(t, prev);
    const double* c = Sample(t, next);
    for (int i = 0; i < 3; ++i) {
      qvel[i] = b.has(kVx) ? x[b.col[kVx + i]] : (c[b.col[kX + i]] - a[b.col[kX + i]]) / dt;
    }
    if (b.has(kWx)) {
      const double w[3] = {x[b.col[kWx]], x[b.col[kWx + 1]], x[b.col[kWx + 2]]};
      RotateBack(qpos + 3, w, qvel + 3);
    } else {
      double qa[4], qc[4];
      for (int i = 0; i < 4; ++i) qa[i] = a[b.col[kQw + i]], qc[i] = c[b.col[kQw + i]];
      mju_normalize4(qa);
      mju_normalize4(qc);
      AngularVelocity(qa, qc, dt, qvel + 3);
    }
  }
  for (const MeasuredJoint& j : joints_) {
    d->qpos[j.qpos] = Sample(t, s)[j.col_q];
    d->qvel[j.qvel] = j.col_v >= 0 ? Sample(t, s)[j.col_v]
                                   : (Sample(t, next)[j.col_q] - Sample(t, prev)[j.col_q]) / dt;
  }
}

void Binding::RefitVelocity(const MeasuredTrajectory& t, int s, const MeasuredBody& b,
                            const double* gravity, double* qvel) const {
  double q0[4], qs[4];
  for (int i = 0; i < 4; ++i) q0[i] = Sample(t, 0)[b.col[kQw + i]], qs[i] = Sample(t, s)[b.col[kQw + i]];
  mju_normalize4(q0);
  mju_normalize4(qs);
  AngularVelocity(q0, qs, t.time[s] - t.time[0], qvel + 3);
  for (int i = 0; i < 3; ++i) {
    if (gravity[i] == 0 && b.has(kVx)) {
      double sum = 0;
      for (int k = 0; k < s; ++k) sum += Sample(t, k)[b.col[kVx + i]];
      qvel[i] = sum / s;
      continue;
    }
    // least squares y = a + v t over samples 0..s-1, y = p - g t^2 / 2
    double tm = 0, ym = 0;
    for (int k = 0; k < s; ++k) {
      const double tk = t.time[k] - t.time[0];
      tm += tk;
      ym += Sample(t, k)[b.col[kX + i]] - 0.5 * gravity[i] * tk * tk;
    }
    tm /= s;
    ym /= s;
    double stt = 0, sty = 0;
    for (int k = 0; k < s; ++k) {
      const double tk = t.time[k] - t.time[0];
      const double yk = Sample(t, k)[b.col[kX + i]] - 0.5 * gravity[i] * tk * tk;
      stt += (tk - tm) * (tk - tm);
      sty += (tk - tm) * (yk - ym);
    }
    qvel[i] = sty / stt + gravity[i] * (t.time[s - 1] - t.time[0]);
  }
}

}  // namespace contactlaws::internal
