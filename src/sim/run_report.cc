// Copyright contactlaws authors.

#include "sim/run_report.h"

#include <fmt/format.h>

#include "sim/timestep_advice.h"

namespace contactlaws {
namespace {

// The first chained point of pair p: its numbers say what an impact's mix
// of points does not (an impact is chained when one of its points is).
const Episode* FirstChainedPoint(const Simulation& sim, int p) {
  for (const Episode& point : sim.contacts().point_episodes()) {
    if (point.pair == p && point.chained()) return &point;
  }
  return nullptr;
}

}  // namespace

std::vector<std::string> ChainedContactWarnings(const Simulation& sim) {
  // the library handles any rise (Episode::max_approach_velocity); a chained
  // contact is one a warning should name, once per tag: many pairs of a tag
  // (balls on a box, a cradle) say one thing
  const ContactModel& cm = sim.contact_model();
  std::vector<std::string> warnings;
  for (const PairTag& tag : cm.tags()) {
    const Episode* first = nullptr;
    int count = 0;
    int pairs = 0;
    for (const int p : tag.pairs) {
      int pair_count = 0;
      for (const Episode& c : sim.contacts().impacts()) {
        if (c.pair != p || !c.chained()) continue;
        if (!first) first = &c;
        ++pair_count;
      }
      count += pair_count;
      pairs += pair_count > 0;
    }
    if (!first) continue;
    const Episode* point = FirstChainedPoint(sim, first->pair);
    if (!point) point = first;
    const std::string others =
        pairs > 1 ? fmt::format(" and {} more pair{} of its tag", pairs - 1, pairs > 2 ? "s" : "")
                  : "";
    warnings.push_back(fmt::format(
        "{}{}: {} collision{} touched slowly and then compressed far faster (the first at "
        "t = {:.6g} s: touched at {:.4g} m/s, compressed at {:.4g} m/s): pushed while in "
        "contact (a pulse through touching bodies, or a body tipping onto the point); the "
        "law's v0 was the largest approach rate, and e_post is taken against it (docs/laws.md, "
        "Touching chains)",
        PairName(sim, first->pair), others, count, count == 1 ? "" : "s", point->time_contact,
        point->impact_velocity, point->max_approach_velocity));
  }
  return warnings;
}

}  // namespace contactlaws
