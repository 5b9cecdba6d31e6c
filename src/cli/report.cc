// Copyright contactlaws authors.

#include "cli/report.h"

#include <fmt/format.h>

#include "cli/cluster.h"
#include "cli/mujoco_warnings.h"
#include "sim/run_report.h"

namespace contactlaws::cli {

void WarnAboutTags(const ContactModel& model, std::set<std::string>* warned) {
  if (!WritesOutputs()) return;  // rank 0 of the job warns
  if (model.tags().empty() && warned->insert("no tags").second) {
    fmt::print(stderr,
               "contactlaws: warning: {}: no contactlaw: tags: MuJoCo's own contact acts on "
               "every pair (docs/tags.md)\n",
               model.source());
  }
  for (const std::string& w : model.warnings()) {
    if (warned->insert(w).second) fmt::print(stderr, "contactlaws: warning: {}\n", w);
  }
}

void ReportSettle(const Simulation& sim) {
  if (sim.settled()) fmt::print(stderr, "contactlaws: {}: {}\n", sim.source(), sim.settled()->Line());
}

namespace {
Spelling spelling = nullptr;  // the command line's: the message as it is
}  // namespace

void SetSpelling(Spelling s) { spelling = s; }

std::string Spelled(const std::string& message) {
  return spelling ? spelling(message) : message;
}

void Warn(const std::string& scene, const std::string& what) {
  if (!WritesOutputs()) return;  // rank 0 of the job warns
  fmt::print(stderr, "contactlaws: warning: {}: {}\n", scene, Spelled(what));
}

std::vector<std::string> RunWarnings(const Simulation& sim, const AdvanceResult& result) {
  std::vector<std::string> warnings;
  if (result.energy_growth) warnings.push_back(*result.energy_growth);
  for (std::string& w : ChainedContactWarnings(sim)) warnings.push_back(std::move(w));
  const double turn = sim.contacts().contact_steps_worst_turn();
  if (sim.contacts().contact_steps().enabled() && turn > kFrozenTurnWarning) {
    warnings.push_back(fmt::format(
        "--contact-steps: a body in contact turned {:.3g} rad within one step (t = {:.6g} s), "
        "beyond {} rad: the configuration frozen over the step moves its contact points and "
        "normals by as much (a die's first rebound at 0.042 rad: 15% off); take a smaller "
        "--timestep (docs/timestep.md, \"Contact steps\")",
        turn, sim.contacts().contact_steps_worst_turn_time(), kFrozenTurnWarning));
  }
  for (const MujocoWarning& w : sim.Warnings()) {
    warnings.push_back(fmt::format("MuJoCo: {} ({} time{})", w.text, w.count,
                                   w.count == 1 ? "" : "s"));
    NoteReportedMujocoWarning(w.text);
  }
  return warnings;
}

std::string Cell(const std::optional<double>& value, const char* format) {
  return value ? fmt::format(fmt::runtime(format), *value) : "-";
}

}  // namespace contactlaws::cli
