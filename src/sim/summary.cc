// Copyright contactlaws authors.

#include "sim/summary.h"

#include <algorithm>
#include <map>

#include "sim/run_report.h"

namespace contactlaws {

RunSummary Summarize(const std::vector<Episode>& impacts, double end_time,
                     const std::vector<uint8_t>& settling) {
  RunSummary s;
  s.impacts = static_cast<int>(impacts.size());
  if (impacts.empty()) return s;

  // the first impact with an approach: bodies placed overlapping and
  // pushed apart at t = 0 rebound from nothing (their e_post would be x / 0),
  // and bodies settling into their contacts are no impact
  const auto first = std::find_if(impacts.begin(), impacts.end(), [&](const Episode& i) {
    const size_t k = &i - impacts.data();
    return i.approached() && !(k < settling.size() && settling[k]);
  });
  if (first != impacts.end()) {
    s.impact_velocity = first->impact_velocity;
    if (!first->open) {
      s.restitution_post = first->restitution_post();
      s.contact_duration = first->time_separation - first->time_contact;
    }
  }

  struct PairRest {
    double longest_closed = 0;
    const Episode* last = nullptr;
  };
  std::map<int, PairRest> pairs;
  for (const Episode& impact : impacts) {
    s.max_depth = std::max(s.max_depth, impact.max_depth);
    s.max_force = std::max(s.max_force, impact.max_force);
    PairRest& pair = pairs[impact.pair];
    if (!impact.open) {
      pair.longest_closed =
          std::max(pair.longest_closed, impact.time_separation - impact.time_contact);
    }
    if (!pair.last || impact.time_contact >= pair.last->time_contact) pair.last = &impact;
  }

  double rest = 0;
  for (const auto& [index, pair] : pairs) {
    const Episode& last = *pair.last;
    if (!last.open) return s;
    if (!(end_time - last.time_contact > pair.longest_closed)) return s;
    rest = std::max(rest, last.time_contact);
  }
  s.time_to_rest = rest;
  return s;
}

RunSummary SummarizeTag(const Simulation& sim, int tag, double end_time) {
  const std::vector<uint8_t> all = SettlingImpacts(sim);
  std::vector<Episode> impacts;
  std::vector<uint8_t> settling;
  for (size_t k = 0; k < sim.contacts().impacts().size(); ++k) {
    const Episode& impact = sim.contacts().impacts()[k];
    if (impact.tag != tag) continue;
    impacts.push_back(impact);
    settling.push_back(all[k]);
  }
  return Summarize(impacts, end_time, settling);
}

}  // namespace contactlaws
