// Copyright contactlaws authors.

#include "cli/report.h"

#include <fmt/format.h>

#include "app/csv_text.h"
#include "app/run_warnings.h"
#include "cli/cluster.h"
#include "cli/mujoco_warnings.h"
#include "cli/options.h"

namespace contactlaws::cli {

void WarnAboutTags(const ContactModel& model, std::set<std::string>* warned) {
  if (!WritesOutputs()) return;  // rank 0 of the job warns
  for (const std::string& w : app::TagWarnings(model)) {
    if (warned->insert(w).second) fmt::print(stderr, "contactlaws: warning: {}\n", w);
  }
}

void ReportSettle(const Simulation& sim) {
  if (sim.settled()) fmt::print(stderr, "contactlaws: {}: {}\n", sim.source(), sim.settled()->Line());
}

void Warn(const std::string& scene, const std::string& what) {
  if (!WritesOutputs()) return;  // rank 0 of the job warns
  fmt::print(stderr, "contactlaws: warning: {}: {}\n", scene, what);
}

std::vector<std::string> RunWarnings(const Simulation& sim, const AdvanceResult& result) {
  std::vector<std::string> warnings = app::RunWarnings(sim, result, Flags());
  for (const MujocoWarning& w : sim.Warnings()) NoteReportedMujocoWarning(w.text);
  return warnings;
}

std::string Cell(const std::optional<double>& value, const char* format) {
  return app::TableCell(value, format);
}

}  // namespace contactlaws::cli
