// Copyright contactlaws authors.

#include "cli/identify.h"

#include <fmt/format.h>

#include "app/replay_job.h"

#include "cli/cluster.h"
#include "cli/sweep.h"
#include "scene/number.h"
#include "scene/tags.h"

namespace contactlaws::cli {

app::ReplayInput InputOf(const ReplayArgs& args) {
  app::ReplayInput input;
  static_cast<app::CommonInput&>(input) = InputOf(static_cast<const CommonArgs&>(args));
  input.start = args.start;
  input.refit_height = ValueOf(args.refit_height);
  input.refit_lead = args.refit_lead;
  input.refit_min_samples = args.refit_min_samples;
  input.metric = args.metric;
  input.weights = args.weights;
  input.length = ValueOf(args.length);
  input.jobs = ValueOf(args.jobs);
  input.law = args.law;
  input.restitution = ValueOf(args.restitution);
  input.set = args.set;
  input.seed = args.seed;
  return input;
}

app::FitInput InputOf(const FitArgs& args) {
  app::FitInput input;
  static_cast<app::ReplayInput&>(input) = InputOf(static_cast<const ReplayArgs&>(args));
  input.params = args.params;
  input.initial = args.initial;
  input.laws = args.laws;
  input.frictions = args.frictions;
  input.budget = args.budget;
  input.folds = ValueOf(args.folds);
  input.trim = ValueOf(args.trim);
  input.profile = args.profile;
  input.profile_points = ValueOf(args.profile_points);
  input.profile_budget = ValueOf(args.profile_budget);
  return input;
}

ReplayOptions ParseReplayOptions(const ReplayArgs& args, const Scene& scene, Metric* metric) {
  ReplayOptions options = app::ReadReplayOptions(Flags(), InputOf(args), scene, metric);
  options.spread = ClusterSpread();
  SetThreadsPerRank(options.jobs);
  return options;
}

uint64_t ParseSeed(const std::string& text) { return app::ReadSeed(Flags(), text); }

MeasuredData DataOf(const ReplayArgs& args) { return app::ReadData(Flags(), "data", args.data); }

app::FitRequest ParseFitRequest(const FitArgs& args, const Scene& scene,
                                const MeasuredData& train_data,
                                std::vector<std::string>* offset_lines) {
  app::FitRequest request =
      app::ReadFitRequest(Flags(), InputOf(args), scene, train_data, offset_lines);
  request.base.spread = ClusterSpread();
  SetThreadsPerRank(request.base.jobs);
  return request;
}

void WriteSimulated(const MeasuredData& data, const app::SimulatedSamples& simulated,
                    CsvFile* file) {
  std::vector<std::string> header = {"trajectory", "time"};
  header.insert(header.end(), simulated.columns.begin(), simulated.columns.end());
  file->Header(header);
  const size_t width = simulated.columns.size();
  std::vector<double> row;
  for (size_t k = 0; k < simulated.time.size(); ++k) {
    row.assign(1, simulated.time[k]);
    row.insert(row.end(), simulated.values.begin() + k * width,
               simulated.values.begin() + (k + 1) * width);
    file->Row({data.trajectories[simulated.trajectory[k]].name}, row);
  }
}

}  // namespace contactlaws::cli
