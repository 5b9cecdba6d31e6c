// Copyright contactlaws authors.

#include "cli/commands.h"

#include <cstdio>

#include <fmt/format.h>

#include "app/restitution_job.h"
#include "cli/cluster.h"
#include "cli/csv_file.h"
#include "cli/sweep.h"

namespace contactlaws::cli {

int RestitutionCommand(const SweepArgs& args) {
  ProgramMonitor monitor(args.quiet);
  app::RestitutionPlan plan = app::PlanRestitution(Flags(), args.scene, InputOf(args), &monitor);
  plan.sweep.advance.stop = &stop_signal;
  plan.sweep.spread = ClusterSpread();
  if (plan.sweep.spread) SetThreadsPerRank(plan.sweep.jobs);
  CsvFile out(args.output);  // an unwritable path fails before the runs
  const app::RestitutionResult result = app::RunRestitution(plan, Flags(), &monitor);
  int status = ExitStatus(result.status);
  WriteTable(result.table, &out);
  out.Commit();
  if (status == 0 && result.incomplete) status = kExitIncomplete;
  if (args.output != "-") {
    std::fputs(result.text.c_str(), args.report);
    fmt::print(args.report, "wrote {}\n", args.output);
  }
  return status;
}

}  // namespace contactlaws::cli
