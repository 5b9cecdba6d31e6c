// Copyright contactlaws authors.

#include <cstdio>

#include <fmt/format.h>

#include "app/fit_job.h"
#include "cli/cluster.h"
#include "cli/commands.h"
#include "cli/identify.h"
#include "cli/sweep.h"

namespace contactlaws::cli {

int FitCommand(const FitArgs& args) {
  const Scene scene = app::LoadReplayScene(args.scene);
  const MeasuredData train_data = DataOf(args);
  std::optional<MeasuredData> validate_data;
  if (args.validate) validate_data = app::ReadData(Flags(), "validate", *args.validate);
  std::vector<std::string> offset_lines;  // GEOM.offset=rest: the data's estimate
  app::FitRequest request = ParseFitRequest(args, scene, train_data, &offset_lines);
  request.stop = app::StopToken(&stop_signal);
  if (!args.quiet && WritesOutputs()) {  // rank 0 of a job reports alone
    request.progress = [](const std::string& line) { fmt::print(stderr, "{}\n", line); };
  }
  // every combination checked before any is fitted
  const app::FitJob job = app::CheckedFitJob(Flags(), scene, train_data,
                                        validate_data ? &*validate_data : nullptr,
                                        std::move(request));

  const std::string dir = CreateDirectory(args.output.value_or("fit"));
  CsvFile ranking(dir + "/ranking.csv"), errors(dir + "/errors.csv");
  CsvFile best_trajectories(dir + "/best_trajectories.csv");
  std::optional<CsvFile> profile_file, fold_file;
  if (args.profile) profile_file.emplace(dir + "/profile.csv");
  if (args.folds) fold_file.emplace(dir + "/folds.csv");
  if (WritesOutputs()) {
    for (const std::string& line : offset_lines) fmt::print(args.report, "{}\n", line);
  }

  const app::FitOutcome outcome = job.Run();
  if (outcome.nothing) {
    fmt::print(stderr, "contactlaws: interrupted before a first evaluation: no file written\n");
    return kExitInterrupted;
  }
  if (!WritesOutputs()) return 0;  // rank 0 of the job writes and prints
  WriteTable(outcome.ranking, &ranking);
  WriteTable(outcome.errors, &errors);
  WriteSimulated(validate_data ? *validate_data : train_data, outcome.best_trajectories,
                 &best_trajectories);
  if (fold_file) WriteTable(outcome.folds, &*fold_file);
  if (outcome.profiled) WriteTable(outcome.profile, &*profile_file);
  std::FILE* file = std::fopen((dir + "/best_tag.txt").c_str(), "w");
  if (!file) throw Error(fmt::format("{}/best_tag.txt: cannot write", dir));
  std::fputs(outcome.best_tag.c_str(), file);
  std::fclose(file);
  ranking.Commit();
  errors.Commit();
  best_trajectories.Commit();
  if (fold_file) fold_file->Commit();
  if (outcome.profiled) profile_file->Commit();
  std::fputs(outcome.report.c_str(), args.report);
  fmt::print(args.report, "wrote {0}/ranking.csv, {0}/errors.csv, {0}/best_trajectories.csv, "
             "{0}/best_tag.txt{1}{2}\n", dir, fold_file ? fmt::format(", {}/folds.csv", dir) : "",
             outcome.profiled ? fmt::format(", {}/profile.csv", dir) : "");
  if (outcome.interrupted) {
    fmt::print(stderr, "contactlaws: interrupted: the best result so far is written\n");
    return kExitInterrupted;
  }
  return 0;
}

}  // namespace contactlaws::cli
