// Copyright contactlaws authors.

#include "contactlaws/replay.h"

#include <cmath>

namespace contactlaws {

namespace {
constexpr const char* kMetricNames[] = {"e_q", "position_rms", "angle_rms", "weighted"};
}  // namespace

std::optional<Metric> ParseMetric(std::string_view name) {
  for (int i = 0; i < 4; ++i) {
    if (name == kMetricNames[i]) return static_cast<Metric>(i);
  }
  return std::nullopt;
}

const char* MetricName(Metric metric) { return kMetricNames[static_cast<int>(metric)]; }

double Score::Of(Metric metric) const {
  switch (metric) {
    case Metric::kEq: return e_q;
    case Metric::kPositionRms: return position_rms;
    case Metric::kAngleRms: return angle_rms;
    case Metric::kWeighted: return weighted;
  }
  return e_q;
}

double RotationAngle(const double q1[4], const double q2[4]) {
  // q1^-1 q2 = conj(q1) q2
  const double w = q1[0] * q2[0] + q1[1] * q2[1] + q1[2] * q2[2] + q1[3] * q2[3];
  const double x = q1[0] * q2[1] - q1[1] * q2[0] - q1[2] * q2[3] + q1[3] * q2[2];
  const double y = q1[0] * q2[2] + q1[1] * q2[3] - q1[2] * q2[0] - q1[3] * q2[1];
  const double z = q1[0] * q2[3] - q1[1] * q2[2] + q1[2] * q2[1] - q1[3] * q2[0];
  return 2.0 * std::atan2(std::sqrt(x * x + y * y + z * z), std::abs(w));
}

void ScoreAccumulator::AddBody(const double p_sim[3], const double p_meas[3],
                               const double* q_sim, const double* q_meas, double length) {
  double dp2 = 0;
  for (int i = 0; i < 3; ++i) dp2 += (p_sim[i] - p_meas[i]) * (p_sim[i] - p_meas[i]);
  double theta2 = 0;
  if (q_sim && q_meas) {
    const double theta = RotationAngle(q_sim, q_meas);
    theta2 = theta * theta;
    theta2_k_ += theta2;
    ++oriented_k_;
  }
  dp2_k_ += dp2;
  eq_k_ += dp2 / length + theta2;
  ++bodies_k_;
}

void ScoreAccumulator::AddJoint(double q_sim, double q_meas) {
  dq2_k_ += (q_sim - q_meas) * (q_sim - q_meas);
  ++joints_k_;
}

void ScoreAccumulator::EndSample() {
  if (bodies_k_ > 0) {
    eq_ += eq_k_ / bodies_k_;
    dp2_ += dp2_k_ / bodies_k_;
  }
  if (oriented_k_ > 0) {
    theta2_ += theta2_k_ / oriented_k_;
    oriented_ = true;
  }
  if (joints_k_ > 0) {
    dq2_ += dq2_k_ / joints_k_;
    jointed_ = true;
  }
  ++samples_;
  eq_k_ = dp2_k_ = theta2_k_ = dq2_k_ = 0;
  bodies_k_ = oriented_k_ = joints_k_ = 0;
}

Score ScoreAccumulator::Finish() const {
  Score s;
  s.samples = samples_;
  if (samples_ == 0) return s;
  const double n = samples_;
  s.e_q = eq_ / n;
  s.position_rms = std::sqrt(dp2_ / n);
  s.angle_rms = oriented_ ? std::sqrt(theta2_ / n) : 0.0;
  s.joint_rms = jointed_ ? std::sqrt(dq2_ / n) : 0.0;
  s.weighted = weights_.position * s.position_rms + weights_.angle * s.angle_rms +
               weights_.joint * s.joint_rms;
  return s;
}

}  // namespace contactlaws
