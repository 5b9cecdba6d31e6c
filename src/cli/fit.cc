// Copyright contactlaws authors.

#include <cstdio>

#include <fmt/format.h>

#include "app/fit_job.h"
#include "cli/cluster.h"
#include "cli/commands.h"
#include "cli/fit_profile.h"
#include "cli/identify.h"
#include "cli/rest_offsets.h"
#include "cli/sweep.h"
#include "scene/number.h"

namespace contactlaws::cli {

app::FitRequest ParseFitRequest(const FitArgs& args, const Scene& scene,
                                const MeasuredData& train_data,
                                std::vector<std::string>* offset_lines) {
  app::FitRequest request;
  request.base = ParseReplayOptions(args, scene, &request.metric);
  request.seed = ParseSeed(args.seed);
  const uint64_t seed = request.seed;
  const RestOffsets rest = WithRestOffsets(args.params, scene, train_data, seed, offset_lines);
  request.parameters =
      UnderOption("--params", [&] { return ParseFitParameters(rest.text, scene.model()); });
  SetRestBounds(rest, &request.parameters);
  if (args.initial) {
    request.initial = UnderOption("--initial", [&] {
      return ParseFitInitial(*args.initial, request.parameters, scene.model());
    });
  }
  request.profile = ParseProfile(args, request.parameters, seed);
  const std::optional<long> budget = ParseWholeNumber(args.budget, 1, 1000000);
  if (!budget) Refuse("--budget", args.budget, "must be a whole number in [1, 1000000]");
  request.budget = static_cast<int>(*budget);
  const int count = static_cast<int>(train_data.trajectories.size());
  if (args.folds) {
    const std::optional<long> folds = ParseWholeNumber(*args.folds, 2, count);
    if (!folds) {
      Refuse("--folds", *args.folds,
             fmt::format("must be a whole number in [2, {}] (the trajectories of {})", count,
                         train_data.source));
    }
    request.folds = static_cast<int>(*folds);
  }
  if (args.trim) {
    const std::optional<double> t = ParseNumber(*args.trim);
    if (!t || !(*t >= 0 && *t < 0.5)) Refuse("--trim", *args.trim, "must be a number in [0, 0.5)");
    request.trim = *t;
  }
  if (args.laws) {
    request.laws.clear();
    for (LawId law : ParseLawList("--laws", *args.laws)) request.laws.emplace_back(law);
  }
  if (args.frictions) {
    if (args.friction) Refuse("--frictions", *args.frictions, "goes without --friction");
    request.frictions.clear();
    for (FrictionKind f : ParseFrictionList("--frictions", *args.frictions)) {
      request.frictions.emplace_back(f);
    }
  }
  return request;
}

app::FitJob CheckedFitJob(const Scene& scene, const MeasuredData& train,
                          const MeasuredData* validate, app::FitRequest request) {
  return UnderOption("--params",
                     [&] { return app::FitJob(scene, train, validate, std::move(request)); });
}

int FitCommand(const FitArgs& args) {
  const Scene scene = app::LoadReplayScene(args.scene);
  const MeasuredData train_data = DataOf(args);
  std::optional<MeasuredData> validate_data;
  if (args.validate) validate_data = ReadData("--validate", *args.validate);
  std::vector<std::string> offset_lines;  // GEOM.offset=rest: the data's estimate
  app::FitRequest request = ParseFitRequest(args, scene, train_data, &offset_lines);
  request.stop = app::StopToken(&stop_signal);
  if (!args.quiet && WritesOutputs()) {  // rank 0 of a job reports alone
    request.progress = [](const std::string& line) { fmt::print(stderr, "{}\n", line); };
  }
  // every combination checked before any is fitted
  const app::FitJob job = CheckedFitJob(scene, train_data,
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
