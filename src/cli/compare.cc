// Copyright contactlaws authors.

#include "cli/commands.h"

#include <fmt/format.h>

#include "cli/csv_file.h"
#include "cli/impact_csv.h"
#include "cli/report.h"
#include "cli/sweep.h"

namespace contactlaws::cli {
namespace {

// A law that reads no restitution once (an elastic one at e = 1); every other
// law at each restitution (the scene's if none given).
std::vector<RunSpec> CompareSpecs(const std::vector<LawKind>& laws,
                                  const std::vector<double>& restitutions) {
  std::vector<RunSpec> specs;
  for (const LawKind law : laws) {
    if (!ReadsRestitution(law)) {
      specs.push_back({law, IsElastic(law) ? std::optional<double>(1.0) : std::nullopt});
    } else if (restitutions.empty()) {
      specs.push_back({law, std::nullopt});
    } else {
      for (const double e : restitutions) specs.push_back({law, e});
    }
  }
  return specs;
}

// The three files of compare, written run by run in order.
class CompareFiles {
 public:
  CompareFiles(const std::string& dir, std::vector<std::string> trajectory_columns)
      : trajectories_(CreateDirectory(dir) + "/trajectories.csv"),
        impacts_(dir + "/impacts.csv"),
        summary_(dir + "/summary.csv") {
    trajectory_columns.insert(trajectory_columns.begin(), {"law", "restitution"});
    trajectories_.Header(trajectory_columns);
    impacts_.Header(ImpactColumns());
    summary_.Header({"law", "restitution", "impacts", "restitution_post", "max_depth",
                     "max_force", "contact_duration", "time_to_rest", "dissipated_energy",
                     "status", "reason"});
  }

  void Write(const RunSpec& spec, const RunOutput& out) {
    const std::string law(LawName(spec.law));
    if (out.status == RunOutput::Status::kOk || out.status == RunOutput::Status::kFailed) {
      // a failed run's rows up to its divergence are valid; an interrupted
      // run's are not written at all
      trajectories_.Write(out.trajectory);
      impacts_.Write(out.impacts);
    }
    const RunSummary& s = out.summary;
    if (out.status == RunOutput::Status::kOk) {
      summary_.Fields({law, Field(out.restitution), Field(s.impacts), Field(s.restitution_post),
                       Field(s.max_depth), Field(s.max_force), Field(s.contact_duration),
                       Field(s.time_to_rest), Field(out.dissipated), "ok", ""});
    } else {
      // a failed run's numbers are not to be trusted: only its status
      summary_.Fields({law, Field(out.restitution), "", "", "", "", "", "", "",
                       StatusName(out.status), out.reason});
    }
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

// One run's line of the printed table.
struct TableRow {
  RunSpec spec;
  RunOutput::Status status;
  std::optional<double> restitution;
  RunSummary s;
  double dissipated;
};

void PrintTable(const std::vector<TableRow>& rows) {
  fmt::print("{:<20} {:>11} {:>10} {:>12} {:>14} {:>14} {:>13} {:>13} {:>15}\n", "law",
             "restitution", "collisions", "first e_post", "max depth (m)", "max force (N)",
             "duration (s)", "at rest (s)", "dissipated (J)");
  for (const TableRow& r : rows) {
    if (r.status != RunOutput::Status::kOk) {
      fmt::print("{:<20} {:>11} {}\n", LawName(r.spec.law), Field(r.restitution),
                 StatusName(r.status));
      continue;
    }
    fmt::print("{:<20} {:>11} {:>10} {:>12} {:>14.6g} {:>14.6g} {:>13} {:>13} {:>15.6g}\n",
               LawName(r.spec.law), Field(r.restitution), r.s.impacts,
               Cell(r.s.restitution_post, "{:.6f}"), r.s.max_depth, r.s.max_force,
               Cell(r.s.contact_duration, "{:.6g}"), Cell(r.s.time_to_rest, "{:.6g}"),
               r.dissipated);
  }
}

}  // namespace

int CompareCommand(const SweepArgs& args) {
  const SweepInputs in = ReadSweepInputs(args, nullptr);
  const SimulationOptions& options = in.common.simulation;
  const std::vector<RunSpec> specs = CompareSpecs(in.laws, in.restitutions);
  const std::vector<std::vector<TimestepAdvice>> advices =
      Prepare(*in.scene, options, specs, in.common.auto_timestep.has_value());

  CompareFiles files(args.output_dir,
                     in.scene->Make(OptionsFor(options, specs.front()))->Columns());
  SweepOptions sweep;
  sweep.advance.duration = in.common.duration;
  sweep.advance.sample_rate = in.common.sample_rate;
  sweep.advance.auto_timestep = in.common.auto_timestep;
  sweep.record = true;
  sweep.impact_rows = args.impacts_per_point ? ImpactRows::kPoints : ImpactRows::kCollisions;
  sweep.jobs = in.jobs;
  sweep.quiet = args.quiet;
  std::vector<TableRow> rows;
  const int status = Sweep(*in.scene, options, specs, advices, sweep, [&](int k, RunOutput& out) {
                             files.Write(specs[k], out);
                             rows.push_back({specs[k], out.status, out.restitution, out.summary,
                                             out.dissipated});
                           });
  files.Commit();

  PrintTable(rows);
  fmt::print("wrote {0}/trajectories.csv, {0}/impacts.csv, {0}/summary.csv\n", args.output_dir);
  return status;
}

}  // namespace contactlaws::cli
