// Copyright contactlaws authors.
//
// Per-trajectory scores in units a person reads, beside the fit's metric
// (docs/identification.md, "Scores a person reads"), and the resting gaps
// summarised per body. Each array is one value per replayed trajectory, in
// the data's order: statistics.h summarises them.

#ifndef CONTACTLAWS_READABLE_H_
#define CONTACTLAWS_READABLE_H_

#include <string>
#include <vector>

#include "contactlaws/rest.h"
#include "contactlaws/score.h"

namespace contactlaws {

struct ScoreArray {
  // "" for the metric itself (ranking.csv's train_mean ...), else the
  // column's stem: "e_q", "position_mm", "angle_deg", "final_angle_deg",
  // "another_face"
  std::string name;
  std::vector<double> values;
  // a share (values 0 or 1): its mean alone is read, with its interval
  bool share = false;
};

// metric's values; e_q's when metric is another; the position and angle
// RMS in mm and degrees; the last sample's rotation (degrees, the largest
// of the bodies'); another face: 1 where a body's last tilt (rest.h)
// exceeds kAnotherFaceTilt.
std::vector<ScoreArray> ReadableScores(const MeasuredData& data,
                                       const std::vector<ReplayedTrajectory>& replayed,
                                       Metric metric);

// One body's resting gaps over the trajectories that end at rest.
struct RestingGaps {
  std::string body;
  int trajectories = 0, at_rest = 0;
  Summary measured_z, simulated_z, gap_z;  // m; gap: simulated - measured
  double gap_z_p25 = 0, gap_z_p75 = 0;     // m, its spread
  Distribution horizontal, angle;          // m, rad
};
std::vector<RestingGaps> SummarizeRestingGaps(const MeasuredData& data,
                                              const std::vector<ReplayedTrajectory>& replayed,
                                              const RestRule& rule, uint64_t seed);

}  // namespace contactlaws

#endif  // CONTACTLAWS_READABLE_H_
