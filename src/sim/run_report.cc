// Copyright contactlaws authors.

#include "contactlaws/run_report.h"

#include <fmt/format.h>

#include "contactlaws/timestep_advice.h"

namespace contactlaws {

std::vector<std::string> ChainedContactWarnings(const Simulation& sim) {
  // an impact's rate falls from its touch on; a contact whose rate rose more
  // than this factor above its touch speed is one a warning should name (the
  // library handles any rise: Impact::max_approach_velocity)
  constexpr double kChainFactor = 2.0;
  const std::vector<Impact>& collisions = sim.contacts().impacts();
  std::vector<std::string> warnings;
  for (int p = 0; p < static_cast<int>(sim.contact_model().pairs().size()); ++p) {
    const Impact* first = nullptr;
    int count = 0;
    for (const Impact& c : collisions) {
      const double touch = std::max(c.impact_velocity, c.touch_v0);
      if (c.pair != p || !(c.max_approach_velocity > kChainFactor * touch)) continue;
      if (!first) first = &c;
      ++count;
    }
    if (!first) continue;
    warnings.push_back(fmt::format(
        "{}: {} collision{} touched slowly and then compressed far faster (the first at "
        "t = {:.6g} s: touched at {:.4g} m/s, compressed at {:.4g} m/s): a pulse through "
        "touching bodies; the law's v0 was the largest approach rate, and e_post is taken "
        "against it (README, Touching chains)",
        PairName(sim, p), count, count == 1 ? "" : "s", first->time_contact,
        first->impact_velocity, first->max_approach_velocity));
  }
  return warnings;
}

}  // namespace contactlaws
