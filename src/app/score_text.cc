// Copyright contactlaws authors.

#include "app/score_text.h"

#include <cmath>
#include <iterator>

#include <fmt/format.h>

namespace contactlaws::app {

namespace {
constexpr double kMm = 1e3;                // per m
constexpr double kDegrees = 180.0 / M_PI;  // per rad
// a plane's normal this close to the world's z (cosine): facing up
constexpr double kUpright = 1 - 1e-9;
}  // namespace

std::string SummaryText(const std::string& name, const Summary& s) {
  return fmt::format("{} mean {:.4g} [{:.4g}, {:.4g}] median {:.4g} [{:.4g}, {:.4g}] p90 {:.4g}",
                     name, s.value.mean, s.mean.lo, s.mean.hi, s.value.median, s.median.lo,
                     s.median.hi, s.value.p90);
}

std::string ReadableText(const std::string& indent, const MeasuredData& data,
                         const std::vector<ReplayedTrajectory>& replayed, Metric metric,
                         uint64_t seed) {
  std::string text;
  for (const ScoreArray& a : ReadableScores(data, replayed, metric)) {
    const Summary s = Summarize(a.values, seed);
    if (a.share) {
      const double n = std::round(s.value.mean * s.count);
      fmt::format_to(std::back_inserter(text),
                 "{}another face: {:.1f}% [{:.1f}, {:.1f}] ({:.0f} of {}: the last tilt above "
                 "{:.0f} degrees)\n",
                 indent, 100 * s.value.mean, 100 * s.mean.lo, 100 * s.mean.hi, n, s.count,
                 kAnotherFaceTilt * kDegrees);
    } else {
      const std::string name = a.name.empty() ? MetricName(metric) : a.name;
      fmt::format_to(std::back_inserter(text), "{}{}\n", indent, SummaryText(name, s));
    }
  }
  return text;
}

std::string RestingGapsText(const std::string& indent, const MeasuredData& data,
                            const std::vector<ReplayedTrajectory>& replayed, uint64_t seed) {
  std::string text;
  const RestRule rule;
  for (const RestingGaps& g : SummarizeRestingGaps(data, replayed, rule, seed)) {
    if (g.at_rest == 0) {
      fmt::format_to(std::back_inserter(text),
                     "{}rest: {}: none of {} trajectories ends at rest (slower than {} m/s "
                     "over its last {} samples)\n",
                     indent, g.body, g.trajectories, rule.speed, rule.samples);
      continue;
    }
    fmt::format_to(std::back_inserter(text),
               "{}rest: {}: {} of {} trajectories end at rest (slower than {} m/s over their last "
               "{} samples): height measured {:.2f} mm [{:.2f}, {:.2f}], simulated {:.2f} mm "
               "[{:.2f}, {:.2f}], gap {:+.2f} mm [{:+.2f}, {:+.2f}] (quartiles {:+.2f}, {:+.2f}); "
               "horizontal gap median {:.1f} mm, p90 {:.1f}; turn median {:.1f} degrees\n",
               indent, g.body, g.at_rest, g.trajectories, rule.speed, rule.samples,
               g.measured_z.value.median * kMm, g.measured_z.median.lo * kMm,
               g.measured_z.median.hi * kMm, g.simulated_z.value.median * kMm,
               g.simulated_z.median.lo * kMm, g.simulated_z.median.hi * kMm,
               g.gap_z.value.median * kMm, g.gap_z.median.lo * kMm, g.gap_z.median.hi * kMm,
               g.gap_z_p25 * kMm, g.gap_z_p75 * kMm, g.horizontal.median * kMm,
               g.horizontal.p90 * kMm, g.angle.median * kDegrees);
  }
  return text;
}

OffsetEstimate EstimateOffset(const Scene& scene, const std::string& geom,
                              const MeasuredData& data, uint64_t seed) {
  const mjModel* m = scene.model();
  const int g = mj_name2id(m, mjOBJ_GEOM, geom.c_str());
  if (g < 0) {
    throw Error(fmt::format("{}: no geom '{}' to estimate the offset of", scene.path(), geom));
  }
  UniqueData d(mj_makeData(m));
  mj_kinematics(m, d.get());
  // a plane's normal is its z axis: the third column of its frame
  if (m->geom_type[g] != mjGEOM_PLANE || d->geom_xmat[9 * g + 8] < kUpright ||
      m->geom_bodyid[g] != 0) {
    throw Error(fmt::format("{}: geom '{}' is not a plane of the world facing up: its offset "
                            "cannot be estimated from where bodies rest",
                            scene.path(), geom));
  }
  OffsetEstimate e;
  e.plane = EstimatePlaneHeight(m, data, RestRule{}, seed);
  e.geom_z = d->geom_xpos[3 * g + 2];
  e.offset = e.plane.height.value.median - e.geom_z;
  e.interval = {e.plane.height.median.lo - e.geom_z, e.plane.height.median.hi - e.geom_z};
  return e;
}

std::string OffsetText(const std::string& geom, const OffsetEstimate& e) {
  const RestRule rule;
  return fmt::format(
      "{0}: {1} of {2} trajectories rest (slower than {3} m/s over their last {4} samples): the "
      "plane they rest on at {5:.3f} mm [{6:.3f}, {7:.3f}] (median resting height less the "
      "support distance, median {8:.3f} mm; 95% interval of the median), {0}.offset {9:+.3f} mm "
      "[{10:+.3f}, {11:+.3f}] from the scene's {12:.3f} mm",
      geom, e.plane.at_rest, e.plane.trajectories, rule.speed, rule.samples,
      e.plane.height.value.median * kMm, e.plane.height.median.lo * kMm,
      e.plane.height.median.hi * kMm, e.plane.support.median * kMm, e.offset * kMm,
      e.interval.lo * kMm, e.interval.hi * kMm, e.geom_z * kMm);
}

}  // namespace contactlaws::app
