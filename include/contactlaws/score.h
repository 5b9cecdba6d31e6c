// Copyright contactlaws authors.
//
// How far a simulated trajectory is from a measured one: every score of
// replay and fit is computed here, one way. Per sample k and measured body
// b (position p, orientation q) or joint j (coordinate q_j):
//
//   dp2(k, b)    = |p_sim - p_meas|^2                         m^2
//   theta(k, b)  = the angle of the rotation q_sim^-1 q_meas   rad, in [0, pi]
//   dq2(k, j)    = (q_sim - q_meas)^2                          rad^2 or m^2
//
// and over the samples (means over every sample and every body or joint
// that has the quantity):
//
//   e_q          = mean of dp2 / L_b + theta^2   (Acosta, Yang & Posa 2022;
//                  L_b a length of body b, the cube's half side there), 1
//   position_rms = sqrt(mean dp2), m
//   angle_rms    = sqrt(mean theta^2), rad
//   joint_rms    = sqrt(mean dq2), rad or m
//   weighted     = P position_rms + A angle_rms + J joint_rms (ScoreWeights)
//
// e_q's first term has units of a length (m^2 / m): the published
// definition, kept as it is so that its numbers compare.

#ifndef CONTACTLAWS_SCORE_H_
#define CONTACTLAWS_SCORE_H_

#include <string>
#include <string_view>
#include <optional>

namespace contactlaws {

enum class Metric { kEq, kPositionRms, kAngleRms, kWeighted };

// "e_q", "position_rms", "angle_rms", "weighted"; nullopt for anything else.
std::optional<Metric> ParseMetric(std::string_view name);
const char* MetricName(Metric metric);

struct ScoreWeights {
  double position = 1.0;  // P, 1/m
  double angle = 1.0;     // A, 1/rad
  double joint = 0.0;     // J, 1/rad or 1/m
};

// A trajectory's scores.
struct Score {
  int samples = 0;  // samples compared
  double e_q = 0;
  double position_rms = 0;  // m
  double angle_rms = 0;     // rad
  double joint_rms = 0;
  double weighted = 0;
  double Of(Metric metric) const;
};

// The angle of the rotation between two unit quaternions (w, x, y, z), rad
// in [0, pi]: 2 atan2(|v|, |w|) of q1^-1 q2, accurate near 0 where 2 acos(w)
// is not.
double RotationAngle(const double q1[4], const double q2[4]);

// Sums the errors of one trajectory, sample by sample.
class ScoreAccumulator {
 public:
  explicit ScoreAccumulator(ScoreWeights weights = {}) : weights_(weights) {}
  // One body at one sample: length L_b (m) for e_q; orientations may be null
  // (a body measured without them).
  void AddBody(const double p_sim[3], const double p_meas[3], const double* q_sim,
               const double* q_meas, double length);
  void AddJoint(double q_sim, double q_meas);
  // Closes sample k (at least one body or joint added since the last).
  void EndSample();
  Score Finish() const;

 private:
  ScoreWeights weights_;
  int samples_ = 0;
  // sums over the samples of each sample's mean
  double eq_ = 0, dp2_ = 0, theta2_ = 0, dq2_ = 0;
  // the current sample's sums and counts
  double eq_k_ = 0, dp2_k_ = 0, theta2_k_ = 0, dq2_k_ = 0;
  int bodies_k_ = 0, oriented_k_ = 0, joints_k_ = 0;
  bool oriented_ = false, jointed_ = false;
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_SCORE_H_
