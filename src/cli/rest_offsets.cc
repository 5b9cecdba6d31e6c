// Copyright contactlaws authors.

#include "cli/rest_offsets.h"

#include <fmt/format.h>

#include "app/score_text.h"

namespace contactlaws::cli {

RestOffsets WithRestOffsets(const std::string& params, const Scene& scene,
                            const MeasuredData& data, uint64_t seed,
                            std::vector<std::string>* lines) {
  constexpr std::string_view kSuffix = ".offset=rest";
  RestOffsets out;
  size_t start = 0;
  while (start <= params.size()) {
    const size_t comma = params.find(',', start);
    std::string item = params.substr(start, comma - start);
    if (item.size() > kSuffix.size() &&
        item.compare(item.size() - kSuffix.size(), kSuffix.size(), kSuffix) == 0) {
      const std::string geom = item.substr(0, item.size() - kSuffix.size());
      try {
        const app::OffsetEstimate e = app::EstimateOffset(scene, geom, data, seed);
        if (!(e.interval.lo < e.interval.hi)) {
          throw Error(fmt::format("the interval [{}, {}] m is empty: nothing to fit within",
                                  e.interval.lo, e.interval.hi));
        }
        lines->push_back(app::OffsetText(geom, e) + ": fitted within that interval");
        out.bounds.emplace_back(geom + ".offset", e.interval);
        item = geom + ".offset=0:1";
      } catch (const Error& error) {
        throw Error(fmt::format("--params: {}: {}", item, error.what()));
      }
    }
    out.text += (out.text.empty() ? "" : ",") + item;
    start = comma == std::string::npos ? params.size() + 1 : comma + 1;
  }
  return out;
}

void SetRestBounds(const RestOffsets& offsets, std::vector<FitParameter>* parameters) {
  for (const auto& [key, interval] : offsets.bounds) {
    for (FitParameter& p : *parameters) {
      if (p.key == key) p.lo = interval.lo, p.hi = interval.hi;
    }
  }
}

}  // namespace contactlaws::cli
