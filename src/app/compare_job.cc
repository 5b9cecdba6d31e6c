// Copyright contactlaws authors.

#include "app/compare_job.h"

#include <iterator>
#include <utility>

#include <fmt/format.h>

#include "app/csv_text.h"
#include "app/impact_table.h"

namespace contactlaws::app {
namespace {

// A law that reads no restitution once (an elastic one at e = 1); every other
// law at each restitution (the scene's if none given); each of those with
// every friction model of frictions (the scene's if none given).
std::vector<RunSpec> CompareSpecs(const std::vector<LawId>& laws,
                                  const std::vector<double>& restitutions,
                                  const std::vector<FrictionKind>& frictions) {
  std::vector<RunSpec> specs;
  auto add = [&](LawId law, std::optional<double> e) {
    if (frictions.empty()) specs.push_back({law, e, std::nullopt});
    for (const FrictionKind friction : frictions) specs.push_back({law, e, friction});
  };
  for (const LawId law : laws) {
    if (!ReadsRestitution(law)) {
      add(law, IsElastic(law) ? std::optional<double>(1.0) : std::nullopt);
    } else if (restitutions.empty()) {
      add(law, std::nullopt);
    } else {
      for (const double e : restitutions) add(law, e);
    }
  }
  return specs;
}

// True when a tagged pair of model can have friction (its larger condim > 1).
bool HasFriction(const ContactModel& model) {
  for (const GeomPair& pair : model.pairs()) {
    if (pair.condim > 1) return true;
  }
  return false;
}

// The run's first cells: law, restitution, and the friction model when the
// runs compare them.
std::string RunCells(const RunSpec& spec, const std::string& restitution, bool frictions) {
  std::string cells = fmt::format("{:<20} {:>11}", LawName(spec.law), restitution);
  if (frictions) {
    cells += fmt::format(" {:<11}", spec.friction ? FrictionName(*spec.friction) : "");
  }
  return cells;
}

}  // namespace

std::string CompareTableText(const std::vector<CompareRow>& rows, bool frictions) {
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "{:<20} {:>11}{} {:>10} {:>12} {:>14} {:>14} {:>13} {:>13} {:>15}\n", "law",
                 "restitution", frictions ? fmt::format(" {:<11}", "friction") : "", "collisions",
                 "first e_post", "max depth (m)", "max force (N)", "duration (s)", "at rest (s)",
                 "dissipated (J)");
  for (const CompareRow& r : rows) {
    const std::string cells = RunCells(r.spec, Field(r.restitution), frictions);
    if (r.status != RunOutput::Status::kComplete) {
      fmt::format_to(out, "{} {}\n", cells, SweepRunStatusName(r.status));
      continue;
    }
    fmt::format_to(out, "{} {:>10} {:>12} {:>14.6g} {:>14.6g} {:>13} {:>13} {:>15.6g}\n", cells,
                   r.s.impacts, TableCell(r.s.restitution_post, "{:.6f}"), r.s.max_depth,
                   r.s.max_force,
                   TableCell(r.s.contact_duration, "{:.6g}"), TableCell(r.s.time_to_rest, "{:.6g}"),
                   r.dissipated);
  }
  return text;
}

std::vector<std::string> SummaryColumns() {
  return {"impacts",           "restitution_post", "max_depth", "max_force", "contact_duration",
          "time_to_rest",      "dissipated_energy", "status",   "reason"};
}

ComparePlan PlanCompare(const OptionReader& reader, const std::string& scene,
                        const SweepInput& input, bool impacts_per_point, SweepMonitor* monitor) {
  ComparePlan plan;
  plan.in = ReadSweepInputs(reader, scene, input, nullptr, monitor);
  const SweepInputs& in = plan.in;
  const SimulationOptions& options = in.common.simulation;
  plan.specs = CompareSpecs(in.laws, in.restitutions, in.frictions);
  plan.frictions = !in.frictions.empty();
  plan.advices =
      Prepare(*in.scene, options, plan.specs, in.common.auto_timestep.has_value(), reader,
              monitor);
  plan.first = in.scene->Make(OptionsFor(options, plan.specs.front()));
  if (plan.first->settled()) monitor->Note(plan.first->source(), plan.first->settled()->Line());
  if (plan.frictions && !HasFriction(plan.first->contact_model())) {
    monitor->Warn(in.scene->path(),
                  reader.Name("frictions") + ": every tagged pair is frictionless (condim 1, as "
                                             "in MuJoCo): the friction models do not act");
  }
  SweepOptions& sweep = plan.sweep;
  sweep.advance.duration = in.common.duration;
  sweep.advance.sample_rate = in.common.sample_rate;
  sweep.advance.auto_timestep = in.common.auto_timestep;
  sweep.record = true;
  sweep.impact_rows = impacts_per_point ? ImpactRows::kPointEpisodes : ImpactRows::kImpacts;
  sweep.jobs = in.jobs;
  return plan;
}

namespace {

using Kind = Column::Kind;

// Each file's first columns: law, restitution, and friction when the runs
// compare friction models.
std::vector<std::pair<std::string, Kind>> RunHeader(bool frictions) {
  std::vector<std::pair<std::string, Kind>> run = {{"law", Kind::kText},
                                                   {"restitution", Kind::kNumber}};
  if (frictions) run.emplace_back("friction", Kind::kText);
  return run;
}

}  // namespace

CompareTables::CompareTables(const ComparePlan& plan)
    : frictions_(plan.frictions), columns_(plan.first->Columns()) {
  std::vector<std::pair<std::string, Kind>> header = RunHeader(frictions_);
  for (const std::string& c : columns_) header.emplace_back(c, Kind::kNumber);
  trajectories_ = Table(header);
  header = RunHeader(frictions_);
  for (const std::string& c : SummaryColumns()) {
    header.emplace_back(c, c == "status" || c == "reason" ? Kind::kText
                           : c == "impacts"               ? Kind::kCount
                                                          : Kind::kNumber);
  }
  summary_ = Table(header);
  header.clear();
  const Table no_impacts = ImpactTable(*plan.first, {});
  for (const Column& c : no_impacts.columns()) header.emplace_back(c.name, c.kind);
  if (frictions_) header.emplace(header.begin() + 2, "friction", Kind::kText);
  impacts_ = Table(header);
}

void CompareTables::Add(const RunSpec& spec, RunOutput& out) {
  std::vector<Cell> prefix = {Text(std::string(LawName(spec.law))),
                              out.restitution ? Number(*out.restitution) : Unknown()};
  if (frictions_) prefix.push_back(Text(std::string(FrictionName(*spec.friction))));
  const bool rows_valid =
      out.status == RunOutput::Status::kComplete || out.status == RunOutput::Status::kFailed;
  if (rows_valid) {
    // a failed run's rows up to its divergence are valid; an interrupted
    // run's are not kept
    for (size_t at = 0; at + columns_.size() <= out.rows.size(); at += columns_.size()) {
      std::vector<Cell> cells = prefix;
      for (size_t c = 0; c < columns_.size(); ++c) cells.push_back(Number(out.rows[at + c]));
      trajectories_.AddRow(cells);
    }
    const Table& log = out.impact_table;
    for (size_t i = 0; i < log.rows(); ++i) {
      std::vector<Cell> cells;
      for (const Column& c : log.columns()) {
        cells.push_back(c.kind == Kind::kText ? Text(c.text[i]) : Cell{c.kind, c.numbers[i], {}});
      }
      if (frictions_) cells.emplace(cells.begin() + 2, prefix[2]);
      impacts_.AddRow(cells);
    }
  }
  std::vector<Cell> cells = prefix;
  const RunSummary& r = out.summary;
  auto known = [](const std::optional<double>& v) { return v ? Number(*v) : Unknown(); };
  if (out.status == RunOutput::Status::kComplete) {
    for (Cell c : {Count(r.impacts), known(r.restitution_post), Number(r.max_depth),
                   Number(r.max_force), known(r.contact_duration), known(r.time_to_rest),
                   Number(out.dissipated), Text("ok"), Text("")}) {
      cells.push_back(std::move(c));
    }
  } else {
    // a failed run's numbers are not to be trusted: only its status
    for (int i = 0; i < 7; ++i) cells.push_back(Unknown());
    cells.push_back(Text(SweepRunStatusName(out.status)));
    cells.push_back(Text(out.reason));
  }
  summary_.AddRow(cells);
  rows_.push_back({spec, out.status, out.restitution, out.summary, out.dissipated});
  out.rows.clear();  // a delivered run's numbers are in the tables
}

}  // namespace contactlaws::app
