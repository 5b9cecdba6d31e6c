// Copyright contactlaws authors.

#include "cli/commands.h"

#include <cstdio>
#include <vector>

#include <fmt/format.h>

#include "app/compare_job.h"
#include "app/impact_table.h"
#include "cli/cluster.h"
#include "cli/csv_file.h"
#include "cli/sweep.h"

namespace contactlaws::cli {
namespace {

using app::RunOutput;
using app::RunSpec;
using app::SweepRunStatusName;
using app::SummaryColumns;

// law, restitution, and friction when the runs compare friction models.
std::vector<std::string> RunColumns(bool frictions) {
  std::vector<std::string> columns = {"law", "restitution"};
  if (frictions) columns.emplace_back("friction");
  return columns;
}

// The run's fields of RunColumns.
std::vector<std::string> RunFields(const RunSpec& spec, const std::optional<double>& restitution) {
  std::vector<std::string> fields = {std::string(LawName(spec.law)), Field(restitution)};
  if (spec.friction) fields.emplace_back(FrictionName(*spec.friction));
  return fields;
}

// The three files of compare, written run by run in order.
class CompareFiles {
 public:
  // frictions: the runs compare friction models (a friction column after
  // restitution in each file)
  CompareFiles(const std::string& dir, const std::vector<std::string>& trajectory_columns,
               std::vector<std::string> impact_columns, bool frictions)
      : trajectories_(CreateDirectory(dir) + "/trajectories.csv"),
        impacts_(dir + "/impacts.csv"),
        summary_(dir + "/summary.csv") {
    std::vector<std::string> columns = RunColumns(frictions);
    columns.insert(columns.end(), trajectory_columns.begin(), trajectory_columns.end());
    trajectories_.Header(columns);
    if (frictions) impact_columns.insert(impact_columns.begin() + 2, "friction");
    impacts_.Header(impact_columns);
    columns = RunColumns(frictions);
    for (std::string& c : SummaryColumns()) columns.push_back(std::move(c));
    summary_.Header(columns);
  }

  void Write(const RunSpec& spec, const RunOutput& out) {
    std::vector<std::string> fields = RunFields(spec, out.restitution);
    if (out.status == RunOutput::Status::kComplete || out.status == RunOutput::Status::kFailed) {
      // a failed run's rows up to its divergence are valid; an interrupted
      // run's are not written at all
      trajectories_.Write(out.trajectory);
      impacts_.Write(out.impacts);
    }
    const RunSummary& s = out.summary;
    if (out.status == RunOutput::Status::kComplete) {
      fields.insert(fields.end(), {Field(s.impacts), Field(s.restitution_post),
                                   Field(s.max_depth), Field(s.max_force),
                                   Field(s.contact_duration), Field(s.time_to_rest),
                                   Field(out.dissipated), "ok", ""});
    } else {
      // a failed run's numbers are not to be trusted: only its status
      fields.insert(fields.end(), {"", "", "", "", "", "", "", SweepRunStatusName(out.status), out.reason});
    }
    summary_.Fields(fields);
    trajectories_.Flush();
    impacts_.Flush();
    summary_.Flush();
  }

  void Commit() {
    trajectories_.Commit();
    impacts_.Commit();
    summary_.Commit();
  }

 private:
  CsvFile trajectories_;
  CsvFile impacts_;
  CsvFile summary_;
};



}  // namespace



int CompareCommand(const SweepArgs& args) {
  ProgramMonitor monitor(args.quiet);
  app::ComparePlan plan =
      app::PlanCompare(Flags(), args.scene, InputOf(args), args.impacts_per_point, &monitor);
  plan.sweep.advance.stop = &stop_signal;
  plan.sweep.spread = ClusterSpread();
  if (plan.sweep.spread) SetThreadsPerRank(plan.sweep.jobs);
  const Scene& scene = *plan.in.scene;
  CompareFiles files(args.output_dir, plan.first->Columns(),
                     TableColumns(app::ImpactTable(*plan.first, {})), plan.frictions);
  std::vector<app::CompareRow> rows;
  const app::SweepStatus status =
      app::Sweep(scene, plan.in.common.simulation, plan.specs, plan.advices, plan.sweep, Flags(),
                 &monitor, [&](int k, app::RunOutput& out) {
                   files.Write(plan.specs[k], out);
                   rows.push_back({plan.specs[k], out.status, out.restitution, out.summary,
                                   out.dissipated});
                 });
  const int exit = ExitStatus(status);
  files.Commit();

  std::fputs(app::CompareTableText(rows, plan.frictions).c_str(), args.report);
  fmt::print(args.report, "wrote {0}/trajectories.csv, {0}/impacts.csv, {0}/summary.csv\n",
             args.output_dir);
  return exit;
}

}  // namespace contactlaws::cli
