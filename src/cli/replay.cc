// Copyright contactlaws authors.

#include <fmt/format.h>

#include "cli/arena.h"
#include "cli/commands.h"
#include "cli/identify.h"
#include "cli/sweep.h"

namespace contactlaws::cli {

int ReplayCommand(const ReplayArgs& args) {
  // the arena sized to the scene: each trajectory's mj_resetData zeroes all of it
  const Scene scene(args.scene, LoadSizedModel(args.scene, Overrides{}));
  const MeasuredData data = ReadData("--data", args.data);
  const Replay replay(scene, data);
  Metric metric = Metric::kEq;
  ReplayOptions options = ParseReplayOptions(args, scene, &metric);
  options.keep_trajectories = args.output.has_value();
  options.should_stop = [] { return stop_signal.load(); };

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
  fmt::print(args.report, "{}: {} trajectories of {} (start {}): {}\n", scene.path(),
             replayed.size(), data.source, args.start, DistributionText(replayed, metric));
  if (metric != Metric::kEq)
    fmt::print(args.report, "  {}\n", DistributionText(replayed, Metric::kEq));
  fmt::print(args.report, "  {}\n  {}\n", DistributionText(replayed, Metric::kPositionRms),
             DistributionText(replayed, Metric::kAngleRms));
  if (const std::string diverged = DivergedText(replayed); !diverged.empty()) {
    fmt::print(stderr, "contactlaws: {}: warning: {}\n", scene.path(), diverged);
  }
  if (args.output)
    fmt::print(args.report, "wrote {0}/replay.csv, {0}/trajectories.csv\n", *args.output);
  return 0;
}

}  // namespace contactlaws::cli
