// Copyright contactlaws authors.
//
// fit's --params items GEOM.offset=rest: a board's offset fitted only within
// the interval the data's resting heights give it (app/score_text.h's
// EstimateOffset).

#ifndef CONTACTLAWS_CLI_REST_OFFSETS_H_
#define CONTACTLAWS_CLI_REST_OFFSETS_H_

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "contactlaws/contactlaws.h"

namespace contactlaws::cli {

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

#endif  // CONTACTLAWS_CLI_REST_OFFSETS_H_
