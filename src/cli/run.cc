// Copyright contactlaws authors.

#include "cli/commands.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/arena.h"
#include "app/impact_table.h"
#include "cli/csv_file.h"
#include "cli/npz_file.h"
#include "cli/report.h"
#include "sim/start_contact.h"
#include "sim/summary.h"
#include "sim/timestep_advice.h"

namespace contactlaws::cli {
namespace {

void PrintRunSummary(const Simulation& sim, double end_time, std::FILE* out) {
  const ContactModel& cm = sim.contact_model();
  fmt::print(out, "{:<20} {:<20} {:>11} {:>10} {:>14} {:>14}\n", "pair", "law", "restitution",
             "collisions", "first e_post", "max force (N)");
  for (int t = 0; t < static_cast<int>(cm.tags().size()); ++t) {
    const PairTag& tag = cm.tags()[t];
    const RunSummary s = SummarizeTag(sim, t, end_time);
    fmt::print(out, "{:<20} {:<20} {:>11} {:>10} {:>14} {:>14.6g}\n", tag.label,
               LawName(tag.law), ReadsRestitution(tag.law) ? Field(tag.restitution) : "-",
               s.impacts, Cell(s.restitution_post, "{:.6f}"), s.max_force);
  }
}

// The trajectory's file: NumPy's archive for a path ending in .npz, CSV
// otherwise.
class TrajectoryFile {
 public:
  explicit TrajectoryFile(const std::string& path) {
    if (HasExtension(path, ".npz")) {
      npz_.emplace(path);
    } else {
      csv_.emplace(path);
    }
  }
  void Header(const std::vector<std::string>& columns) {
    npz_ ? npz_->Header(columns) : csv_->Header(columns);
  }
  void Row(const std::vector<double>& values) { npz_ ? npz_->Row(values) : csv_->Row(values); }
  void Commit() { npz_ ? npz_->Commit() : csv_->Commit(); }

 private:
  std::optional<NpzFile> npz_;
  std::optional<CsvFile> csv_;
};

// The impact log of sim, in rows, committed.
void WriteImpacts(const Simulation& sim, app::ImpactRows rows, CsvFile* impacts) {
  WriteTable(app::ImpactTable(sim, app::ImpactsOf(sim.contacts(), rows)), impacts);
  impacts->Commit();
}

}  // namespace

int RunCommand(const RunArgs& args) {
  // one file is written by one writer
  if (args.output && args.impacts && SamePath(*args.output, *args.impacts)) {
    Refuse("--impacts", *args.impacts, "is the --output path too: give the two files two paths");
  }
  // a .npy would name every column in its header, which numpy.load refuses
  // beyond 10000 bytes (49 balls' columns)
  if (args.output && HasExtension(*args.output, ".npy")) {
    Refuse("--output", *args.output,
           "is refused: give FILE.npz, NumPy's archive (a .npy's header names every column, "
           "which numpy.load refuses for many bodies)");
  }
  const CommonOptions common = ParseCommon(args);
  SimulationOptions options = common.simulation;
  const std::optional<AutoTimestepOptions>& auto_timestep = common.auto_timestep;
  ParseLawOverrides(args.law, args.restitution, &options.overrides);
  const Scene scene(args.scene, app::LoadSizedModel(args.scene, options.overrides));
  std::unique_ptr<Simulation> sim = scene.Make(options);
  ReportSettle(*sim);
  std::set<std::string> warned;
  WarnAboutTags(sim->contact_model(), &warned);

  // open the outputs before the run: an unwritable path fails now
  std::optional<TrajectoryFile> trajectory;
  std::optional<CsvFile> impacts;
  if (args.output) trajectory.emplace(*args.output);
  if (args.impacts) impacts.emplace(*args.impacts);

  const std::vector<StartContact> starts = StartContacts(sim.get());
  for (const std::string& w : DeepStartWarnings(*sim, starts, kCommandLineSpelling)) Warn(scene.path(), w);
  // the timestep's advice at the start: its warnings, for a fixed step
  // without contact steps; otherwise only a divergence's message reads it,
  // and it is taken then, from a new start (its look-ahead steps the scene
  // at its own step: a fifth of box_stack.xml's run with contact steps)
  std::optional<std::vector<TimestepAdvice>> advice;
  if (!auto_timestep && !sim->contacts().contact_steps().enabled()) {
    advice = AdviseTimestep(sim.get(), starts);
    for (const std::string& w : TimestepWarnings(*sim, *advice, kCommandLineSpelling)) Warn(scene.path(), w);
  } else {
    mj_forward(sim->model(), sim->data());  // as AdviseTimestep leaves the data
  }
  if (trajectory) trajectory->Header(sim->Columns());
  AdvanceOptions advance;
  advance.duration = common.duration;
  advance.sample_rate = trajectory ? common.sample_rate : 0.0;
  advance.auto_timestep = auto_timestep;
  advance.stop = &stop_signal;
  const AdvanceResult result =
      Advance(sim.get(), advance, [&](const std::vector<double>& row) { trajectory->Row(row); });
  if (result.status == AdvanceResult::Status::kInterrupted) {
    fmt::print(stderr, "contactlaws: interrupted at t = {:.6g} s: no file written\n",
               sim->time());
    return kExitInterrupted;
  }
  for (const std::string& w : RunWarnings(*sim, result)) Warn(scene.path(), w);

  // what was computed up to a divergence is valid, and written
  const double end_time = result.divergence ? result.divergence->time : sim->time();
  if (trajectory) trajectory->Commit();
  if (impacts) {
    WriteImpacts(*sim,
                 args.impacts_per_point ? app::ImpactRows::kPointEpisodes
                                        : app::ImpactRows::kImpacts,
                 &*impacts);
  }
  PrintRunSummary(*sim, end_time, args.output && *args.output == "-" ? stderr : stdout);
  if (result.divergence) {
    if (!advice) {
      std::unique_ptr<Simulation> start = scene.Make(options);
      advice = AdviseTimestep(start.get(), StartContacts(start.get()));
    }
    fmt::print(stderr, "contactlaws: {}: run stopped: diverged at {}\n", scene.path(),
               DivergenceMessage(*sim, *result.divergence, *advice, kCommandLineSpelling));
    return kExitIncomplete;
  }
  return 0;
}

}  // namespace contactlaws::cli
