// Copyright contactlaws authors.

#include <fmt/format.h>

#include "cli/arena.h"
#include "cli/commands.h"
#include "cli/identify.h"
#include "cli/summary_text.h"
#include "cli/sweep.h"

namespace contactlaws::cli {
namespace {

// What --settle moved over the trajectories' starts, in one line.
std::string SettledText(const std::vector<ReplayedTrajectory>& replayed) {
  int starts = 0, farthest = -1;
  for (size_t i = 0; i < replayed.size(); ++i) {
    if (replayed[i].settled_bodies == 0) continue;
    ++starts;
    if (farthest < 0 || replayed[i].settled_distance > replayed[farthest].settled_distance) {
      farthest = static_cast<int>(i);
    }
  }
  if (starts == 0) return "settle: no body touches another at any trajectory's start: nothing moved";
  return fmt::format("settled the bodies in contact at the start of {} of {} trajectories: the "
                     "farthest moved {:.3g} m (trajectory {})",
                     starts, replayed.size(), replayed[farthest].settled_distance, farthest);
}

}  // namespace

int ReplayCommand(const ReplayArgs& args) {
  // the arena sized to the scene: each trajectory's mj_resetData zeroes all of it
  const Scene scene(args.scene, LoadSizedModel(args.scene, Overrides{}));
  const MeasuredData data = DataOf(args);
  const Replay replay(scene, data);
  Metric metric = Metric::kEq;
  ReplayOptions options = ParseReplayOptions(args, scene, &metric);
  options.keep_trajectories = args.output.has_value();
  options.should_stop = [] { return stop_signal.load(); };
  const uint64_t seed = ParseSeed(args.seed);
  std::optional<OffsetEstimate> offset;  // refused before the runs
  if (args.rest_plane) offset = EstimateOffset(scene, *args.rest_plane, data, seed);

  // the outputs opened before the runs: an unwritable folder fails now
  std::optional<CsvFile> scores, simulated;
  if (args.output) {
    const std::string dir = CreateDirectory(*args.output);
    scores.emplace(dir + "/replay.csv");
    simulated.emplace(dir + "/trajectories.csv");
  }
  const std::vector<ReplayedTrajectory> replayed = replay.Run(options);
  for (const ReplayedTrajectory& r : replayed) {
    if (r.status == ReplayedTrajectory::Status::kInterrupted) {
      fmt::print(stderr, "contactlaws: interrupted: no file written\n");
      return kExitInterrupted;
    }
  }
  if (scores) {
    scores->Header(ReplayColumns());
    for (size_t i = 0; i < replayed.size(); ++i) {
      scores->Fields(ReplayFields(data.trajectories[i], replayed[i]));
    }
    WriteSimulated(data, replayed, &*simulated);
    scores->Commit();
    simulated->Commit();
  }
  fmt::print(args.report, "{}: {} trajectories of {} (start {}; means and medians with their "
             "95% bootstrap interval over the trajectories):\n", scene.path(), replayed.size(),
             data.source, args.start);
  PrintReadable(args.report, "  ", data, replayed, metric, seed);
  PrintRestingGaps(args.report, "  ", data, replayed, seed);
  if (offset) fmt::print(args.report, "  {}\n", OffsetText(*args.rest_plane, *offset));
  if (const std::string diverged = DivergedText(replayed); !diverged.empty()) {
    fmt::print(stderr, "contactlaws: {}: warning: {}\n", scene.path(), diverged);
  }
  if (options.simulation.settle) {
    fmt::print(stderr, "contactlaws: {}: {}\n", scene.path(), SettledText(replayed));
  }
  if (args.output)
    fmt::print(args.report, "wrote {0}/replay.csv, {0}/trajectories.csv\n", *args.output);
  return 0;
}

}  // namespace contactlaws::cli
