// Copyright contactlaws authors.
//
// What replay and fit print of the per-trajectory scores (readable.h): each
// mean and median with its 95% bootstrap interval, the share ending on
// another face, the resting gaps per body; and the board's offset estimated
// from where the data rest (rest.h), for --rest-plane and GEOM.offset=rest.

#ifndef CONTACTLAWS_CLI_SUMMARY_TEXT_H_
#define CONTACTLAWS_CLI_SUMMARY_TEXT_H_

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "contactlaws/contactlaws.h"

namespace contactlaws::cli {

// "NAME mean M [LO, HI] median D [LO, HI] p90 P"
std::string SummaryText(const std::string& name, const Summary& s);

// A line per readable score of replayed (ReadableScores), each indented by
// indent; the metric's first.
void PrintReadable(std::FILE* out, const std::string& indent, const MeasuredData& data,
                   const std::vector<ReplayedTrajectory>& replayed, Metric metric,
                   uint64_t seed);

// A line per measured body: its resting height measured and simulated, and
// their gap, in mm, over the trajectories that end at rest.
void PrintRestingGaps(std::FILE* out, const std::string& indent, const MeasuredData& data,
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

// --params' GEOM.offset=rest items, bounded by their estimates: text is
// --params with each of them as GEOM.offset=0:1, a placeholder range that
// ParseFitParameters checks like any other (the key, the geom, a model
// edit), and bounds the estimates' intervals by key, set on the parsed
// parameters as numbers (SetRestBounds); lines: what each says, to print.
struct RestOffsets {
  std::string text;
  std::vector<std::pair<std::string, Interval>> bounds;
};
RestOffsets WithRestOffsets(const std::string& params, const Scene& scene,
                            const MeasuredData& data, uint64_t seed,
                            std::vector<std::string>* lines);
// parameters' ranges set to offsets' bounds (a key's interval, exactly).
void SetRestBounds(const RestOffsets& offsets, std::vector<FitParameter>* parameters);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_SUMMARY_TEXT_H_
