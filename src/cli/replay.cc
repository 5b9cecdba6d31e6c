// Copyright contactlaws authors.

#include <cstdio>

#include <fmt/format.h>

#include "app/replay_job.h"
#include "cli/commands.h"
#include "cli/identify.h"

namespace contactlaws::cli {

int ReplayCommand(const ReplayArgs& args) {
  const Scene scene = app::LoadReplayScene(args.scene);
  const MeasuredData data = DataOf(args);
  app::ReplayRequest request;
  request.options = ParseReplayOptions(args, scene, &request.metric);
  request.seed = ParseSeed(args.seed);
  request.rest_plane = args.rest_plane;
  request.keep_trajectories = args.output.has_value();
  request.stop = app::StopToken(&stop_signal);
  const app::ReplayJob job(scene, data, std::move(request));  // refused before the runs

  // the outputs opened before the runs: an unwritable folder fails now
  std::optional<CsvFile> scores, simulated;
  if (args.output) {
    const std::string dir = CreateDirectory(*args.output);
    scores.emplace(dir + "/replay.csv");
    simulated.emplace(dir + "/trajectories.csv");
  }
  const app::ReplayResult result = job.Run();
  if (result.interrupted) {
    fmt::print(stderr, "contactlaws: interrupted: no file written\n");
    return kExitInterrupted;
  }
  if (scores) {
    WriteTable(app::ScoresTable(result.scores), &*scores);
    WriteSimulated(data, result.simulated, &*simulated);
    scores->Commit();
    simulated->Commit();
  }
  std::fputs(result.report.c_str(), args.report);
  if (!result.diverged.empty()) {
    fmt::print(stderr, "contactlaws: {}: warning: {}\n", scene.path(), result.diverged);
  }
  if (!result.settled.empty()) {
    fmt::print(stderr, "contactlaws: {}: {}\n", scene.path(), result.settled);
  }
  if (args.output)
    fmt::print(args.report, "wrote {0}/replay.csv, {0}/trajectories.csv\n", *args.output);
  return 0;
}

}  // namespace contactlaws::cli
