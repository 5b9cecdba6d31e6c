// Copyright contactlaws authors.

#include "cli/commands.h"

#include <fmt/format.h>

#include "cli/csv_file.h"
#include "app/impact_table.h"
#include "cli/csv_file.h"
#include "cli/report.h"
#include "cli/sweep.h"
#include "sim/timestep_advice.h"

namespace contactlaws::cli {
namespace {

// The restitution sweep of the paper's Fig. 7.
constexpr char kDefaultSweep[] = "0.1:1.0:0.1";

// A run's first episode, as far as it is known: a run that finished has one
// (or none), and it has ended (closed) or not.
struct FirstEpisode {
  RunSpec spec;
  std::optional<Episode> first;  // a finished run's first episode
  bool closed = false;
};

FirstEpisode FirstEpisodeOf(const RunSpec& spec, const RunOutput& run) {
  FirstEpisode episode{spec, std::nullopt, false};
  if (run.status == RunOutput::Status::kOk && run.first) {
    episode.first = run.first;
    episode.closed = !run.first->open;
  }
  return episode;
}

// The CSV row: empty fields for what is not known.
std::vector<std::string> CsvFields(const FirstEpisode& e) {
  const std::optional<Episode>& first = e.first;
  auto if_known = [&](double v) { return first ? Field(v) : std::string(); };
  auto if_closed = [&](double v) { return e.closed ? Field(v) : std::string(); };
  return {std::string(LawName(e.spec.law)),
          Field(*e.spec.restitution),
          first ? if_closed(first->restitution_post()) : "",
          first ? if_known(first->impact_velocity) : "",
          first ? if_known(first->max_depth) : "",
          first ? if_known(first->max_force) : "",
          first ? if_closed(first->time_separation - first->time_contact) : ""};
}

void PrintTable(const std::vector<FirstEpisode>& rows, const std::string& output, std::FILE* out) {
  fmt::print(out, "{:<20} {:>11} {:>12} {:>12} {:>14} {:>14} {:>13}\n", "law", "restitution",
             "e_post", "exact e_post", "max depth (m)", "max force (N)", "duration (s)");
  for (const FirstEpisode& r : rows) {
    std::optional<double> post, duration;
    if (r.closed) {
      post = r.first->restitution_post();
      duration = r.first->time_separation - r.first->time_contact;
    }
    const std::optional<double> exact = EffectiveRestitution(r.spec.law, *r.spec.restitution);
    fmt::print(out, "{:<20} {:>11} {:>12} {:>12} {:>14} {:>14} {:>13}\n", LawName(r.spec.law),
               Field(*r.spec.restitution), Cell(post, "{:.6f}"), Cell(exact, "{:.6f}"),
               r.first ? fmt::format("{:.6g}", r.first->max_depth) : "-",
               r.first ? fmt::format("{:.6g}", r.first->max_force) : "-", Cell(duration, "{:.6g}"));
  }
  fmt::print(out,
             "exact e_post: the closed form a (1 + e) = ln((1 + a) / (1 - a e)), "
             "gravity neglected\nwrote {}\n",
             output);
}

}  // namespace

int RestitutionCommand(const SweepArgs& args) {
  const SweepInputs in = ReadSweepInputs(args, kDefaultSweep);
  const SimulationOptions& options = in.common.simulation;
  const Scene& scene = *in.scene;
  std::vector<RunSpec> specs;
  for (const LawId law : in.laws) {
    for (const double e : in.restitutions) specs.push_back({law, e, std::nullopt});
  }
  const std::vector<std::vector<TimestepAdvice>> advices =
      Prepare(scene, options, specs, in.common.auto_timestep.has_value());

  CsvFile out(args.output);
  out.Header({"law", "restitution", "restitution_post", "impact_velocity", "max_depth",
              "max_force", "contact_duration"});
  std::vector<FirstEpisode> rows;
  int incomplete = 0;
  SweepOptions sweep;
  sweep.advance.duration = in.common.duration;
  sweep.advance.until_first_episode = true;
  sweep.advance.auto_timestep = in.common.auto_timestep;
  sweep.advance.stop = &stop_signal;
  sweep.jobs = in.jobs;
  sweep.quiet = args.quiet;
  int status = Sweep(
      scene, options, specs, advices, sweep, [&](int k, RunOutput& run) {
        const FirstEpisode episode = FirstEpisodeOf(specs[k], run);
        if (run.status == RunOutput::Status::kOk && !episode.closed) {
          ++incomplete;
          Warn(scene.path(), fmt::format("{}: {} within --duration={} s", Describe(specs[k]),
                                         run.first ? "the first contact did not end"
                                                   : "no contact",
                                         in.common.duration));
        }
        // an interrupted run leaves no row; a failed one an empty row
        if (run.status != RunOutput::Status::kOk && run.status != RunOutput::Status::kFailed) {
          return;
        }
        out.Fields(CsvFields(episode));
        rows.push_back(episode);
      });
  out.Commit();
  if (status == 0 && incomplete) status = kExitIncomplete;
  if (args.output != "-") PrintTable(rows, args.output, args.report);
  return status;
}

}  // namespace contactlaws::cli
