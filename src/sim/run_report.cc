// Copyright contactlaws authors.

#include "sim/run_report.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "sim/estimate.h"
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

// The speed at which gravity alone sinks the bodies of impact c into their
// contact from touching, to its largest depth D: sqrt(2 a D), a the most
// either movable side's weight presses it in along the normal (the other
// held: the box under a ball holds it up); m/s.
double SinkingSpeed(const Simulation& sim, const Episode& c) {
  const ContactModel& cm = sim.contact_model();
  const GeomPair& pair = cm.pairs()[c.pair];
  // c.normal points from the pair's body[0] to body[1]: gravity along -n
  // presses body[1] in, along +n body[0]
  const double along = mju_dot3(sim.model()->opt.gravity, c.normal);
  double press = 0;
  if (!Immovable(cm, pair.body[1])) press = std::max(press, -along);
  if (!Immovable(cm, pair.body[0])) press = std::max(press, along);
  return std::sqrt(2 * press * c.max_depth);
}

// Whether chained impact c is bodies settling under their load: touched
// slower than the law's floor of v0 (placed touching, or come to rest) and
// compressed no faster than kChainFactor times gravity sinks them to its
// depth, or than the scene's contacts that settle so compressed (settling,
// m/s: the load of the bodies above reaches a contact whichever way it
// points, a ball wedged between two others). A pulse through touching
// bodies is far faster (a cradle, whose balls gravity does not press
// together, has none).
bool SettledUnderLoad(const Simulation& sim, const Episode& c, double settling = 0) {
  return c.impact_velocity < c.touch_v0 &&
         c.max_approach_velocity <= kChainFactor * std::max(SinkingSpeed(sim, c), settling);
}

// The fastest compression of the scene's contacts that settle under their
// own bodies' weight (SettledUnderLoad), m/s.
double SceneSettling(const Simulation& sim) {
  double settling = 0;
  for (const Episode& c : sim.contacts().impacts()) {
    if (SettledUnderLoad(sim, c)) settling = std::max(settling, c.max_approach_velocity);
  }
  return settling;
}

}  // namespace

std::vector<uint8_t> SettlingImpacts(const Simulation& sim) {
  const double scene_settling = SceneSettling(sim);
  std::vector<uint8_t> settling;
  for (const Episode& c : sim.contacts().impacts()) {
    settling.push_back(SettledUnderLoad(sim, c, scene_settling));
  }
  return settling;
}

std::vector<std::string> ChainedContactWarnings(const Simulation& sim, const Spelling& spelling) {
  // the library handles any rise (Episode::max_approach_velocity); a chained
  // contact is one a warning should name, once per tag: many pairs of a tag
  // (balls on a box, a cradle) say one thing
  const ContactModel& cm = sim.contact_model();
  const double scene_settling = SceneSettling(sim);
  std::vector<std::string> warnings;
  for (const PairTag& tag : cm.tags()) {
    const Episode* first = nullptr;
    int count = 0;
    int pairs = 0;
    for (const int p : tag.pairs) {
      int pair_count = 0;
      for (const Episode& c : sim.contacts().impacts()) {
        if (c.pair != p || !c.chained() || SettledUnderLoad(sim, c, scene_settling)) continue;
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
        // a contact there at the start touched at no speed, -0 for one found closing
        std::max(0.0, point->impact_velocity), point->max_approach_velocity));
  }
  // bodies that merely started touching: one line for the scene
  const Episode* fastest = nullptr;
  int settling = 0;
  for (const Episode& c : sim.contacts().impacts()) {
    if (!c.chained() || !SettledUnderLoad(sim, c, scene_settling)) continue;
    ++settling;
    if (!fastest || c.max_approach_velocity > fastest->max_approach_velocity) fastest = &c;
  }
  if (fastest) {
    // a settled run's resting contacts came to rest in it: no advice
    const std::string advice =
        sim.settled() ? ""
                      : fmt::format("; {} starts the bodies at the depth their contacts carry them",
                                    spelling.set("settle"));
    warnings.push_back(fmt::format(
        "{} contact{} touching at rest sank into {} spring{} under the load, up to {:.4g} m/s "
        "against the law's v0 of {:.3g} m/s ({}, t = {:.6g} s): no impact and no push{}",
        settling, settling == 1 ? "" : "s", settling == 1 ? "its" : "their",
        settling == 1 ? "" : "s", fastest->max_approach_velocity, fastest->touch_v0,
        PairName(sim, fastest->pair), fastest->time_contact, advice));
  }
  return warnings;
}

}  // namespace contactlaws
