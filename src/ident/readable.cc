// Copyright contactlaws authors.

#include "contactlaws/fit.h"

#include <algorithm>
#include <cmath>

namespace contactlaws {

namespace {
constexpr double kMm = 1e3;                // per m
constexpr double kDegrees = 180.0 / M_PI;  // per rad
}  // namespace

std::vector<ScoreArray> ReadableScores(const MeasuredData& data,
                                       const std::vector<ReplayedTrajectory>& replayed,
                                       Metric metric) {
  std::vector<ScoreArray> arrays = {{"", {}}};
  if (metric != Metric::kEq) arrays.push_back({"e_q", {}});
  arrays.push_back({"position_mm", {}});
  arrays.push_back({"angle_deg", {}});
  arrays.push_back({"final_angle_deg", {}});
  arrays.push_back({"another_face", {}, true});
  const std::vector<std::vector<EndGap>> gaps = EndGaps(data, replayed, RestRule{});
  for (size_t i = 0; i < replayed.size(); ++i) {
    const Score& s = replayed[i].score;
    double angle = 0, tilt = 0;
    for (const EndGap& g : gaps[i]) angle = std::max(angle, g.angle), tilt = std::max(tilt, g.tilt);
    size_t a = 0;
    arrays[a++].values.push_back(s.Of(metric));
    if (metric != Metric::kEq) arrays[a++].values.push_back(s.e_q);
    arrays[a++].values.push_back(s.position_rms * kMm);
    arrays[a++].values.push_back(s.angle_rms * kDegrees);
    arrays[a++].values.push_back(angle * kDegrees);
    arrays[a++].values.push_back(tilt > kAnotherFaceTilt ? 1.0 : 0.0);
  }
  return arrays;
}

std::vector<RestingGaps> SummarizeRestingGaps(const MeasuredData& data,
                                              const std::vector<ReplayedTrajectory>& replayed,
                                              const RestRule& rule, uint64_t seed) {
  const std::vector<MeasuredBodyColumns> bodies = MeasuredBodies(data);
  const std::vector<std::vector<EndGap>> gaps = EndGaps(data, replayed, rule);
  std::vector<RestingGaps> out;
  for (size_t b = 0; b < bodies.size(); ++b) {
    RestingGaps r;
    r.body = bodies[b].name;
    std::vector<double> measured, simulated, gap, horizontal, angle;
    for (const std::vector<EndGap>& g : gaps) {
      if (g.size() != bodies.size()) continue;
      ++r.trajectories;
      if (!g[b].at_rest) continue;
      ++r.at_rest;
      measured.push_back(g[b].measured_z);
      simulated.push_back(g[b].simulated_z);
      gap.push_back(g[b].simulated_z - g[b].measured_z);
      horizontal.push_back(g[b].horizontal);
      angle.push_back(g[b].angle);
    }
    r.measured_z = Summarize(measured, seed);
    r.simulated_z = Summarize(simulated, seed);
    r.gap_z = Summarize(gap, seed);
    std::sort(gap.begin(), gap.end());
    r.gap_z_p25 = Quantile(gap, 0.25);
    r.gap_z_p75 = Quantile(gap, 0.75);
    r.horizontal = Distribute(horizontal);
    r.angle = Distribute(angle);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace contactlaws
