// Copyright contactlaws authors.

#include "app/run_warnings.h"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "sim/run_report.h"

namespace contactlaws::app {

std::vector<std::string> TagWarnings(const ContactModel& model) {
  std::vector<std::string> warnings;
  if (model.tags().empty()) {
    warnings.push_back(fmt::format(
        "{}: no contactlaw: tags: MuJoCo's own contact acts on every pair (docs/tags.md)",
        model.source()));
  }
  for (const std::string& w : model.warnings()) {
    if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
  }
  return warnings;
}

std::vector<std::string> RunWarnings(const Simulation& sim, const AdvanceResult& result,
                                     const OptionReader& options) {
  std::vector<std::string> warnings;
  if (result.energy_growth) warnings.push_back(*result.energy_growth);
  for (std::string& w : ChainedContactWarnings(sim, options.spelling())) warnings.push_back(std::move(w));
  const double turn = sim.contacts().contact_steps_worst_turn();
  if (sim.contacts().contact_steps().enabled() && turn > kFrozenTurnWarning) {
    warnings.push_back(fmt::format(
        "{}: a body in contact turned {:.3g} rad within one step (t = {:.6g} s; the first step "
        "beyond {} rad at t = {:.6g} s): the configuration frozen over the step moves its "
        "contact points and normals by as much (a die's first rebound at 0.042 rad: 15% off); "
        "take a smaller {} (docs/timestep.md, \"Contact steps\")",
        options.Name("contact_steps"), turn, sim.contacts().contact_steps_worst_turn_time(),
        kFrozenTurnWarning, sim.contacts().contact_steps_first_far_turn_time(),
        options.Name("timestep")));
  }
  for (const MujocoWarning& w : sim.Warnings()) {
    warnings.push_back(fmt::format("MuJoCo: {} ({} time{})", w.text, w.count,
                                   w.count == 1 ? "" : "s"));
  }
  return warnings;
}

}  // namespace contactlaws::app
