// Copyright contactlaws authors.

#include "app/restitution_job.h"

#include <iterator>
#include <optional>

#include <fmt/format.h>

#include "app/csv_text.h"

namespace contactlaws::app {
namespace {

// A run's first episode, as far as it is known: a run that finished has one
// (or none), and it has ended (closed) or not.
struct FirstEpisode {
  RunSpec spec;
  std::optional<Episode> first;  // a finished run's first episode
  bool closed = false;
};

FirstEpisode FirstEpisodeOf(const RunSpec& spec, const RunOutput& run) {
  FirstEpisode episode{spec, std::nullopt, false};
  if (run.status == RunOutput::Status::kComplete && run.first) {
    episode.first = run.first;
    episode.closed = !run.first->open;
  }
  return episode;
}

// The table's row: not known (NaN) where there is no such value.
std::vector<Cell> Cells(const FirstEpisode& e) {
  const std::optional<Episode>& first = e.first;
  auto if_known = [&](double v) { return first ? Number(v) : Unknown(); };
  auto if_closed = [&](double v) { return e.closed ? Number(v) : Unknown(); };
  return {Text(std::string(LawName(e.spec.law))),
          Number(*e.spec.restitution),
          first ? if_closed(first->restitution_post()) : Unknown(),
          first ? if_known(first->impact_velocity) : Unknown(),
          first ? if_known(first->max_depth) : Unknown(),
          first ? if_known(first->max_force) : Unknown(),
          first ? if_closed(first->time_separation - first->time_contact) : Unknown()};
}

std::string TableText(const std::vector<FirstEpisode>& rows) {
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "{:<20} {:>11} {:>12} {:>12} {:>14} {:>14} {:>13}\n", "law", "restitution",
                 "e_post", "exact e_post", "max depth (m)", "max force (N)", "duration (s)");
  for (const FirstEpisode& r : rows) {
    std::optional<double> post, duration;
    if (r.closed) {
      post = r.first->restitution_post();
      duration = r.first->time_separation - r.first->time_contact;
    }
    const std::optional<double> exact = EffectiveRestitution(r.spec.law, *r.spec.restitution);
    fmt::format_to(out, "{:<20} {:>11} {:>12} {:>12} {:>14} {:>14} {:>13}\n",
                   LawName(r.spec.law), Field(*r.spec.restitution), TableCell(post, "{:.6f}"),
                   TableCell(exact, "{:.6f}"),
                   r.first ? fmt::format("{:.6g}", r.first->max_depth) : "-",
                   r.first ? fmt::format("{:.6g}", r.first->max_force) : "-",
                   TableCell(duration, "{:.6g}"));
  }
  fmt::format_to(out,
                 "exact e_post: the closed form a (1 + e) = ln((1 + a) / (1 - a e)), "
                 "gravity neglected\n");
  return text;
}

}  // namespace

RestitutionPlan PlanRestitution(const OptionReader& reader, const std::string& scene,
                                const SweepInput& input, SweepMonitor* monitor) {
  RestitutionPlan plan;
  plan.in = ReadSweepInputs(reader, scene, input, kDefaultSweep, monitor);
  for (const LawId law : plan.in.laws) {
    for (const double e : plan.in.restitutions) plan.specs.push_back({law, e, std::nullopt});
  }
  plan.advices = Prepare(*plan.in.scene, plan.in.common.simulation, plan.specs,
                         plan.in.common.auto_timestep.has_value(), reader, monitor);
  plan.sweep.advance.duration = plan.in.common.duration;
  plan.sweep.advance.until_first_episode = true;
  plan.sweep.advance.auto_timestep = plan.in.common.auto_timestep;
  plan.sweep.jobs = plan.in.jobs;
  return plan;
}

RestitutionResult RunRestitution(const RestitutionPlan& plan, const OptionReader& reader,
                                 SweepMonitor* monitor) {
  RestitutionResult result;
  result.table = Table({{"law", Column::Kind::kText},
                        {"restitution", Column::Kind::kNumber},
                        {"restitution_post", Column::Kind::kNumber},
                        {"impact_velocity", Column::Kind::kNumber},
                        {"max_depth", Column::Kind::kNumber},
                        {"max_force", Column::Kind::kNumber},
                        {"contact_duration", Column::Kind::kNumber}});
  const Scene& scene = *plan.in.scene;
  std::vector<FirstEpisode> rows;
  result.status = Sweep(
      scene, plan.in.common.simulation, plan.specs, plan.advices, plan.sweep, reader, monitor,
      [&](int k, RunOutput& run) {
        const FirstEpisode episode = FirstEpisodeOf(plan.specs[k], run);
        if (run.status == RunOutput::Status::kComplete && !episode.closed) {
          ++result.incomplete;
          monitor->Warn(scene.path(),
                        fmt::format("{}: {} within {}={} s", Describe(plan.specs[k]),
                                    run.first ? "the first contact did not end" : "no contact",
                                    reader.Name("duration"), plan.in.common.duration));
        }
        // an interrupted run leaves no row; a failed one a row not known
        if (run.status != RunOutput::Status::kComplete && run.status != RunOutput::Status::kFailed) {
          return;
        }
        result.table.AddRow(Cells(episode));
        rows.push_back(episode);
      });
  result.text = TableText(rows);
  return result;
}

}  // namespace contactlaws::app
