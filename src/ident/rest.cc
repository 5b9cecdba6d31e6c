// Copyright contactlaws authors.

#include "contactlaws/fit.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"

namespace contactlaws {

namespace {

const double* Sample(const MeasuredData& data, const MeasuredTrajectory& t, int k) {
  return t.values.data() + static_cast<size_t>(k) * data.columns.size();
}

// The orientation of body in sample x: measured, else the model's own.
void Orientation(const mjModel* m, int body, const MeasuredBodyColumns& b, const double* x,
                 double q[4]) {
  for (int i = 0; i < 4; ++i) q[i] = b.qw >= 0 ? x[b.qw + i] : m->body_quat[4 * body + i];
  mju_normalize4(q);
}

// max over the geom's points x of x . u (u a unit vector in its own frame)
double Support(const mjModel* m, int g, const double u[3]) {
  const mjtNum* s = m->geom_size + 3 * g;
  switch (m->geom_type[g]) {
    case mjGEOM_BOX: return s[0] * std::abs(u[0]) + s[1] * std::abs(u[1]) + s[2] * std::abs(u[2]);
    case mjGEOM_SPHERE: return s[0];
    case mjGEOM_CAPSULE: return s[0] + s[1] * std::abs(u[2]);
    case mjGEOM_CYLINDER:
      return s[1] * std::abs(u[2]) + s[0] * std::sqrt(std::max(0.0, 1 - u[2] * u[2]));
    case mjGEOM_ELLIPSOID:
      return std::sqrt(s[0] * s[0] * u[0] * u[0] + s[1] * s[1] * u[1] * u[1] +
                       s[2] * s[2] * u[2] * u[2]);
    default: return std::nan("");
  }
}

}  // namespace

std::vector<MeasuredBodyColumns> MeasuredBodies(const MeasuredData& data) {
  std::vector<MeasuredBodyColumns> bodies;
  for (const std::string& column : data.columns) {
    if (column.size() < 3 || column.compare(column.size() - 2, 2, ".x") != 0) continue;
    const std::string name = column.substr(0, column.size() - 2);
    const int x = data.Column(column);
    if (data.Column(name + ".y") != x + 1 || data.Column(name + ".z") != x + 2) continue;
    MeasuredBodyColumns b{name, x, data.Column(name + ".qw")};
    if (b.qw >= 0 && (data.Column(name + ".qx") != b.qw + 1 ||
                      data.Column(name + ".qy") != b.qw + 2 ||
                      data.Column(name + ".qz") != b.qw + 3)) {
      b.qw = -1;
    }
    bodies.push_back(b);
  }
  return bodies;
}

bool EndsAtRest(const MeasuredData& data, const MeasuredTrajectory& t,
                const MeasuredBodyColumns& body, const RestRule& rule) {
  const int n = t.samples();
  if (rule.samples < 1 || n < rule.samples + 1) return false;
  for (int k = n - rule.samples; k < n; ++k) {
    const double* a = Sample(data, t, k - 1) + body.x;
    const double* b = Sample(data, t, k) + body.x;
    const double d = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                               (b[2] - a[2]) * (b[2] - a[2]));
    if (d > rule.speed * (t.time[k] - t.time[k - 1])) return false;
  }
  return true;
}

double SupportDistance(const mjModel* m, int body, const double q[4], bool resting) {
  double deepest = -mjMAXVAL;
  for (int g = m->body_geomadr[body]; g >= 0 && g < m->body_geomadr[body] + m->body_geomnum[body];
       ++g) {
    if (m->geom_contype[g] == 0 && m->geom_conaffinity[g] == 0) continue;
    double qg[4], down_world[3] = {0, 0, -1}, u[3], p[3];
    mju_mulQuat(qg, q, m->geom_quat + 4 * g);
    mju_negQuat(qg, qg);  // the inverse: the world's -z in the geom's frame
    mju_rotVecQuat(u, down_world, qg);
    if (resting) {  // on the face (or end, or side) nearest to facing down
      int axis = 0;
      for (int i = 1; i < 3; ++i) axis = std::abs(u[i]) > std::abs(u[axis]) ? i : axis;
      for (int i = 0; i < 3; ++i) u[i] = i == axis ? (u[i] < 0 ? -1.0 : 1.0) : 0.0;
    }
    mju_rotVecQuat(p, m->geom_pos + 3 * g, q);
    const double h = Support(m, g, u);
    if (std::isnan(h)) {
      throw Error(fmt::format("body '{}': geom {} is of a type whose support distance is not "
                              "known (box, sphere, capsule, cylinder, ellipsoid)",
                              mj_id2name(m, mjOBJ_BODY, body), g));
    }
    deepest = std::max(deepest, h - p[2]);
  }
  if (deepest == -mjMAXVAL) {
    throw Error(fmt::format("body '{}': no colliding geom to rest on",
                            mj_id2name(m, mjOBJ_BODY, body)));
  }
  return deepest;
}

PlaneEstimate EstimatePlaneHeight(const mjModel* m, const MeasuredData& data,
                                  const RestRule& rule, uint64_t seed) {
  PlaneEstimate e;
  std::vector<double> heights, supports;
  for (const MeasuredBodyColumns& b : MeasuredBodies(data)) {
    const int body = mj_name2id(m, mjOBJ_BODY, b.name.c_str());
    if (body < 0) throw Error(fmt::format("{}: body '{}' is not in the scene", data.source, b.name));
    for (const MeasuredTrajectory& t : data.trajectories) {
      ++e.trajectories;
      if (!EndsAtRest(data, t, b, rule)) continue;
      ++e.at_rest;
      // the window's mean position and last orientation: the tracking's
      // noise averaged over the samples found at rest
      double z = 0;
      for (int k = t.samples() - rule.samples - 1; k < t.samples(); ++k) {
        z += Sample(data, t, k)[b.x + 2];
      }
      z /= rule.samples + 1;
      double q[4];
      Orientation(m, body, b, Sample(data, t, t.samples() - 1), q);
      const double support = SupportDistance(m, body, q, true);
      supports.push_back(support);
      heights.push_back(z - support);
    }
  }
  if (e.at_rest < kMinimumAtRest) {
    throw Error(fmt::format("{}: {} of {} trajectories come to rest (slower than {} m/s over "
                            "their last {} samples): an offset from their resting height needs "
                            "at least {}",
                            data.source, e.at_rest, e.trajectories, rule.speed, rule.samples,
                            kMinimumAtRest));
  }
  e.height = Summarize(heights, seed);
  e.support = Distribute(supports);
  return e;
}

std::vector<std::vector<EndGap>> EndGaps(const MeasuredData& data,
                                         const std::vector<ReplayedTrajectory>& replayed,
                                         const RestRule& rule) {
  const std::vector<MeasuredBodyColumns> bodies = MeasuredBodies(data);
  std::vector<std::vector<EndGap>> gaps(replayed.size());
  for (size_t i = 0; i < replayed.size() && i < data.trajectories.size(); ++i) {
    const MeasuredTrajectory& t = data.trajectories[i];
    const double* x = Sample(data, t, t.samples() - 1);
    const std::vector<double>& s = replayed[i].last;
    if (s.size() != data.columns.size()) continue;  // not replayed
    for (const MeasuredBodyColumns& b : bodies) {
      EndGap g;
      g.at_rest = EndsAtRest(data, t, b, rule);
      g.measured_z = x[b.x + 2];
      g.simulated_z = s[b.x + 2];
      g.horizontal = std::hypot(s[b.x] - x[b.x], s[b.x + 1] - x[b.x + 1]);
      if (b.qw >= 0) {
        double qm[4], qs[4];
        for (int k = 0; k < 4; ++k) qm[k] = x[b.qw + k], qs[k] = s[b.qw + k];
        mju_normalize4(qm);
        mju_normalize4(qs);
        g.angle = RotationAngle(qs, qm);
        // the world's vertical in each body's frame
        double up[3] = {0, 0, 1}, um[3], us[3], inv[4];
        mju_negQuat(inv, qm);
        mju_rotVecQuat(um, up, inv);
        mju_negQuat(inv, qs);
        mju_rotVecQuat(us, up, inv);
        g.tilt = std::acos(std::clamp(mju_dot3(um, us), -1.0, 1.0));
      }
      gaps[i].push_back(g);
    }
  }
  return gaps;
}

}  // namespace contactlaws
