// Copyright contactlaws authors.

#include "cli/commands.h"

#include <cstdio>
#include <iterator>
#include <memory>

#include <fmt/format.h>

#include "cli/csv_file.h"
#include "app/impact_table.h"
#include "cli/csv_file.h"
#include "cli/report.h"
#include "cli/sweep.h"
#include "sim/summary.h"
#include "sim/timestep_advice.h"

namespace contactlaws::cli {
namespace {

// A law that reads no restitution once (an elastic one at e = 1); every other
// law at each restitution (the scene's if none given); each of those with
// every friction model of --frictions (the scene's if none given).
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
    if (out.status == RunOutput::Status::kOk || out.status == RunOutput::Status::kFailed) {
      // a failed run's rows up to its divergence are valid; an interrupted
      // run's are not written at all
      trajectories_.Write(out.trajectory);
      impacts_.Write(out.impacts);
    }
    const RunSummary& s = out.summary;
    if (out.status == RunOutput::Status::kOk) {
      fields.insert(fields.end(), {Field(s.impacts), Field(s.restitution_post),
                                   Field(s.max_depth), Field(s.max_force),
                                   Field(s.contact_duration), Field(s.time_to_rest),
                                   Field(out.dissipated), "ok", ""});
    } else {
      // a failed run's numbers are not to be trusted: only its status
      fields.insert(fields.end(), {"", "", "", "", "", "", "", StatusName(out.status), out.reason});
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
    if (r.status != RunOutput::Status::kOk) {
      fmt::format_to(out, "{} {}\n", cells, StatusName(r.status));
      continue;
    }
    fmt::format_to(out, "{} {:>10} {:>12} {:>14.6g} {:>14.6g} {:>13} {:>13} {:>15.6g}\n", cells,
                   r.s.impacts, Cell(r.s.restitution_post, "{:.6f}"), r.s.max_depth, r.s.max_force,
                   Cell(r.s.contact_duration, "{:.6g}"), Cell(r.s.time_to_rest, "{:.6g}"),
                   r.dissipated);
  }
  return text;
}

std::vector<std::string> SummaryColumns() {
  return {"impacts",           "restitution_post", "max_depth", "max_force", "contact_duration",
          "time_to_rest",      "dissipated_energy", "status",   "reason"};
}

ComparePlan PlanCompare(const SweepArgs& args) {
  ComparePlan plan;
  plan.in = ReadSweepInputs(args, nullptr);
  const SweepInputs& in = plan.in;
  const SimulationOptions& options = in.common.simulation;
  plan.specs = CompareSpecs(in.laws, in.restitutions, in.frictions);
  plan.frictions = !in.frictions.empty();
  plan.advices = Prepare(*in.scene, options, plan.specs, in.common.auto_timestep.has_value());
  plan.first = in.scene->Make(OptionsFor(options, plan.specs.front()));
  ReportSettle(*plan.first);
  if (plan.frictions && !HasFriction(plan.first->contact_model())) {
    Warn(in.scene->path(), "--frictions: every tagged pair is frictionless (condim 1, as in "
                           "MuJoCo): the friction models do not act");
  }
  SweepOptions& sweep = plan.sweep;
  sweep.advance.duration = in.common.duration;
  sweep.advance.sample_rate = in.common.sample_rate;
  sweep.advance.auto_timestep = in.common.auto_timestep;
  sweep.advance.stop = &stop_signal;
  sweep.record = true;
  sweep.impact_rows =
      args.impacts_per_point ? app::ImpactRows::kPointEpisodes : app::ImpactRows::kImpacts;
  sweep.jobs = in.jobs;
  sweep.quiet = args.quiet;
  return plan;
}

int CompareCommand(const SweepArgs& args) {
  const ComparePlan plan = PlanCompare(args);
  const Scene& scene = *plan.in.scene;
  CompareFiles files(args.output_dir, plan.first->Columns(),
                     TableColumns(app::ImpactTable(*plan.first, {})), plan.frictions);
  std::vector<CompareRow> rows;
  const int status = Sweep(scene, plan.in.common.simulation, plan.specs, plan.advices, plan.sweep,
                           [&](int k, RunOutput& out) {
                             files.Write(plan.specs[k], out);
                             rows.push_back({plan.specs[k], out.status, out.restitution,
                                             out.summary, out.dissipated});
                           });
  files.Commit();

  std::fputs(CompareTableText(rows, plan.frictions).c_str(), args.report);
  fmt::print(args.report, "wrote {0}/trajectories.csv, {0}/impacts.csv, {0}/summary.csv\n",
             args.output_dir);
  return status;
}

}  // namespace contactlaws::cli
