// Copyright contactlaws authors.
//
// What replay and fit say of the per-trajectory scores (fit.h's ReadableScores) to a
// person: each mean and median with its 95% bootstrap interval, the share
// ending on another face, the resting gaps per body; and the board's offset
// estimated from where the data rest (fit.h). The numbers themselves are
// the results' columns; these are their printed lines, the same for the
// command line and Python.

#ifndef CONTACTLAWS_APP_SCORE_TEXT_H_
#define CONTACTLAWS_APP_SCORE_TEXT_H_

#include <cstdint>
#include <string>
#include <vector>

#include "contactlaws/contactlaws.h"

namespace contactlaws::app {

// "NAME mean M [LO, HI] median D [LO, HI] p90 P"
std::string SummaryText(const std::string& name, const Summary& s);

// A line per readable score of replayed (ReadableScores), each indented by
// indent and ended by a newline; the metric's first.
std::string ReadableText(const std::string& indent, const MeasuredData& data,
                         const std::vector<ReplayedTrajectory>& replayed, Metric metric,
                         uint64_t seed);

// A line per measured body: its resting height measured and simulated, and
// their gap, in mm, over the trajectories that end at rest.
std::string RestingGapsText(const std::string& indent, const MeasuredData& data,
                            const std::vector<ReplayedTrajectory>& replayed, uint64_t seed);

// The offset along its z that puts plane geom GEOM where the data rest
// (EstimatePlaneHeight less the geom's height now): the estimate and its
// interval. Throws Error, naming the geom, for a geom that is not a plane
// facing up in the world, and as EstimatePlaneHeight does.
struct OffsetEstimate {
  PlaneEstimate plane;
  double geom_z = 0;  // the plane's height in the scene, m
  double offset = 0;  // the median's, m
  Interval interval;  // the median's 95% interval, as an offset, m
};
OffsetEstimate EstimateOffset(const Scene& scene, const std::string& geom,
                              const MeasuredData& data, uint64_t seed);
std::string OffsetText(const std::string& geom, const OffsetEstimate& e);

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_SCORE_TEXT_H_
