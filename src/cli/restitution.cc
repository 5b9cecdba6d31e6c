// Copyright contactlaws authors.

#include "cli/commands.h"

#include <fmt/format.h>

#include "cli/csv_file.h"
#include "cli/impact_csv.h"
#include "cli/report.h"
#include "cli/sweep.h"

namespace contactlaws::cli {
namespace {

// The restitution sweep of the paper's Fig. 7.
constexpr char kDefaultSweep[] = "0.1:1.0:0.1";

}  // namespace


int RestitutionCommand(const SweepArgs& args) {
  const CommonOptions common = ParseCommon(args);
  const SimulationOptions& options = common.simulation;
  const std::vector<LawKind> laws = ParseLawList("--laws", args.laws);
  const int jobs = Jobs(args.jobs);
  const std::vector<double> restitutions =
      ParseRestitutionList("--restitution", args.restitution.value_or(kDefaultSweep));
  std::vector<RunSpec> specs;
  for (LawKind law : laws) {
    for (double e : restitutions) specs.push_back({law, e});
  }
  const Scene scene(args.scene);
  const std::vector<std::vector<TimestepAdvice>> advices =
      Prepare(scene, options, specs, common.auto_timestep.has_value());

  CsvFile out(args.output);
  out.Header({"law", "restitution", "restitution_post", "impact_velocity", "max_depth",
              "max_force", "contact_duration"});
  struct Row {
    RunSpec spec;
    std::optional<Impact> first;
  };
  std::vector<Row> rows;
  int incomplete = 0;
  AdvanceOptions advance;
  advance.duration = common.duration;
  advance.until_first_episode = true;
  advance.auto_timestep = common.auto_timestep;
  int status = Sweep(
      scene, options, specs, advices, advance, Record::kSummary, jobs, args.quiet,
      [&](int k, RunOutput& run) {
        const RunSpec& spec = specs[k];
        const std::optional<Impact>& first = run.first;
        const bool closed = run.status == RunOutput::Status::kOk && first && !first->open;
        if (run.status == RunOutput::Status::kOk && !closed) {
          ++incomplete;
          Warn(scene.path(), fmt::format("{}: {} within --duration={} s", Describe(spec),
                                         first ? "the first contact did not end" : "no contact",
                                         common.duration));
        }
        if (run.status != RunOutput::Status::kOk && run.status != RunOutput::Status::kFailed) {
          return;  // interrupted: no row
        }
        const bool known = run.status == RunOutput::Status::kOk && first;
        auto if_known = [&](double v) { return known ? Field(v) : std::string(); };
        auto if_closed = [&](double v) { return closed ? Field(v) : std::string(); };
        out.Fields({std::string(LawName(spec.law)), Field(*spec.restitution),
                    first ? if_closed(first->restitution_post()) : "",
                    first ? if_known(first->impact_velocity) : "",
                    first ? if_known(first->max_depth) : "",
                    first ? if_known(first->max_force) : "",
                    first ? if_closed(first->time_separation - first->time_contact) : ""});
        rows.push_back({spec, known ? first : std::nullopt});
      });
  out.Commit();
  if (status == 0 && incomplete) status = kExitIncomplete;

  if (args.output != "-") {
    fmt::print("{:<20} {:>11} {:>12} {:>12} {:>14} {:>14} {:>13}\n", "law", "restitution",
               "e_post", "exact e_post", "max depth (m)", "max force (N)", "duration (s)");
    for (const Row& r : rows) {
      std::optional<double> post, duration, exact;
      if (r.first && !r.first->open) {
        post = r.first->restitution_post();
        duration = r.first->time_separation - r.first->time_contact;
      }
      if (r.spec.law != LawKind::kKelvinVoigt && *r.spec.restitution > 0) {
        exact = ExactRebound(HysteresisCoefficient(r.spec.law, *r.spec.restitution));
      }
      fmt::print("{:<20} {:>11} {:>12} {:>12} {:>14} {:>14} {:>13}\n", LawName(r.spec.law),
                 Field(*r.spec.restitution), Cell(post, "{:.6f}"), Cell(exact, "{:.6f}"),
                 r.first ? fmt::format("{:.6g}", r.first->max_depth) : "-",
                 r.first ? fmt::format("{:.6g}", r.first->max_force) : "-",
                 Cell(duration, "{:.6g}"));
    }
    fmt::print("exact e_post: the closed form a (1 + e) = ln((1 + a) / (1 - a e)), "
               "gravity neglected\nwrote {}\n", args.output);
  }
  return status;
}

}  // namespace contactlaws::cli
