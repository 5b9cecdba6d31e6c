// Copyright contactlaws authors.

#include "cli/commands.h"

#include <fmt/format.h>

#include "cli/csv_file.h"
#include "cli/impact_csv.h"
#include "cli/report.h"
#include "cli/sweep.h"

namespace contactlaws::cli {

int CompareCommand(const SweepArgs& args) {
  const CommonOptions common = ParseCommon(args);
  const SimulationOptions& options = common.simulation;
  const std::vector<LawKind> laws = ParseLawList("--laws", args.laws);
  const int jobs = Jobs(args.jobs);
  std::vector<double> restitutions;
  if (args.restitution) restitutions = ParseRestitutionList("--restitution", *args.restitution);

  // Hertz once; every other law at each restitution (the scene's if none given)
  std::vector<RunSpec> specs;
  for (LawKind law : laws) {
    if (law == LawKind::kHertz) {
      specs.push_back({law, 1.0});
    } else if (restitutions.empty()) {
      specs.push_back({law, std::nullopt});
    } else {
      for (double e : restitutions) specs.push_back({law, e});
    }
  }
  const Scene scene(args.scene);
  const std::vector<std::vector<TimestepAdvice>> advices =
      Prepare(scene, options, specs, common.auto_timestep.has_value());

  CreateDirectory(args.output_dir);
  CsvFile trajectories(args.output_dir + "/trajectories.csv");
  CsvFile impacts(args.output_dir + "/impacts.csv");
  CsvFile summary(args.output_dir + "/summary.csv");
  {
    std::vector<std::string> columns = {"law", "restitution"};
    for (std::string& c : scene.Make(OptionsFor(options, specs.front()))->Columns()) {
      columns.push_back(std::move(c));
    }
    trajectories.Header(columns);
  }
  impacts.Header(ImpactColumns());
  summary.Header({"law", "restitution", "impacts", "restitution_post", "max_depth", "max_force",
                  "contact_duration", "time_to_rest", "dissipated_energy", "status", "reason"});

  struct Row {
    RunSpec spec;
    RunOutput::Status status;
    double restitution;
    RunSummary s;
    double dissipated;
  };
  std::vector<Row> rows;
  AdvanceOptions advance;
  advance.duration = common.duration;
  advance.sample_rate = common.sample_rate;
  advance.auto_timestep = common.auto_timestep;
  const int status = Sweep(
      scene, options, specs, advices, advance, Record::kEverything, jobs, args.quiet,
      [&](int k, RunOutput& out) {
        const RunSpec& spec = specs[k];
        const std::string law(LawName(spec.law));
        if (out.status == RunOutput::Status::kOk || out.status == RunOutput::Status::kFailed) {
          // a failed run's rows up to its divergence are valid; an
          // interrupted run's are not written at all
          trajectories.Write(out.trajectory);
          impacts.Write(out.impacts);
        }
        const RunSummary& s = out.summary;
        if (out.status == RunOutput::Status::kOk) {
          summary.Fields({law, Field(out.restitution), Field(s.impacts),
                          Field(s.restitution_post), Field(s.max_depth), Field(s.max_force),
                          Field(s.contact_duration), Field(s.time_to_rest),
                          Field(out.dissipated), "ok", ""});
        } else {
          // a failed run's numbers are not to be trusted: only its status
          summary.Fields({law, Field(out.restitution), "", "", "", "", "", "", "",
                          StatusName(out.status), out.reason});
        }
        rows.push_back({spec, out.status, out.restitution, s, out.dissipated});
        trajectories.Flush();
        impacts.Flush();
        summary.Flush();
      });
  trajectories.Commit();
  impacts.Commit();
  summary.Commit();

  fmt::print("{:<20} {:>11} {:>8} {:>12} {:>14} {:>14} {:>13} {:>13} {:>15}\n", "law",
             "restitution", "impacts", "first e_post", "max depth (m)", "max force (N)",
             "duration (s)", "at rest (s)", "dissipated (J)");
  for (const Row& r : rows) {
    if (r.status != RunOutput::Status::kOk) {
      fmt::print("{:<20} {:>11} {}\n", LawName(r.spec.law), Field(r.restitution),
                 StatusName(r.status));
      continue;
    }
    fmt::print("{:<20} {:>11} {:>8} {:>12} {:>14.6g} {:>14.6g} {:>13} {:>13} {:>15.6g}\n",
               LawName(r.spec.law), Field(r.restitution), r.s.impacts,
               Cell(r.s.restitution_post, "{:.6f}"), r.s.max_depth, r.s.max_force,
               Cell(r.s.contact_duration, "{:.6g}"), Cell(r.s.time_to_rest, "{:.6g}"),
               r.dissipated);
  }
  fmt::print("wrote {0}/trajectories.csv, {0}/impacts.csv, {0}/summary.csv\n", args.output_dir);
  return status;
}

}  // namespace contactlaws::cli
