// Copyright contactlaws authors.

#include "cli/identify.h"

#include <fmt/format.h>

#include "app/replay_job.h"

#include "cli/cluster.h"
#include "cli/sweep.h"
#include "scene/number.h"
#include "scene/tags.h"

namespace contactlaws::cli {

namespace {

// "P,A" or "P,A,J", each >= 0.
ScoreWeights ParseWeights(const std::string& text) {
  std::vector<double> w;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = text.find(',', start);
    const std::string part = text.substr(start, comma - start);
    const std::optional<double> v = ParseNumber(part);
    if (!v || *v < 0) Refuse("--weights", text, "must be P,A or P,A,J: numbers >= 0");
    w.push_back(*v);
    start = comma == std::string::npos ? text.size() + 1 : comma + 1;
  }
  if (w.size() < 2 || w.size() > 3) Refuse("--weights", text, "must be P,A or P,A,J: numbers >= 0");
  return {w[0], w[1], w.size() == 3 ? w[2] : 0.0};
}

int ParseCount(std::string_view option, const std::string& text, long lo) {
  const std::optional<long> v = ParseWholeNumber(text, lo, 1000000);
  if (!v) Refuse(option, text, fmt::format("must be a whole number in [{}, 1000000]", lo));
  return static_cast<int>(*v);
}

}  // namespace

ReplayOptions ParseReplayOptions(const ReplayArgs& args, const Scene& scene, Metric* metric) {
  ReplayOptions options;
  const std::optional<Metric> m = ParseMetric(args.metric);
  if (!m) Refuse("--metric", args.metric, "must be e_q, position_rms, angle_rms or weighted");
  *metric = *m;
  if (args.weights && *m != Metric::kWeighted) {
    Refuse("--weights", *args.weights, "goes with --metric weighted");
  }
  if (args.weights) options.weights = ParseWeights(*args.weights);
  if (args.length) options.length = ParsePositive("--length", *args.length, "m");

  CommonOptions common = ParseCommon(args);
  options.simulation = common.simulation;
  // the laws need the contact-aware step; MuJoCo's own contact its scene's
  bool tagged = false;
  for (int i = 0; i < scene.model()->ntext; ++i) {
    const char* name = scene.model()->names + scene.model()->name_textadr[i];
    tagged = tagged || std::string_view(name).rfind(kPairTagPrefix, 0) == 0;
  }
  options.auto_timestep = common.auto_timestep;
  if (!args.timestep && !options.auto_timestep && tagged) options.auto_timestep.emplace();
  ParseLawOverrides(args.law, args.restitution, &options.simulation.overrides);
  for (const std::string& word : args.set) {
    const size_t eq = word.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == word.size()) {
      Refuse("--set", word, "must be KEY=VALUE, a contactlaw tag key and its value");
    }
    options.simulation.overrides.keys.emplace_back(word.substr(0, eq), word.substr(eq + 1));
  }

  if (args.start == "refit") {
    options.start = StartRule::kRefit;
  } else if (args.start != "first") {
    Refuse("--start", args.start, "must be first or refit");
  }
  if (args.refit_height) options.refit.height = ParseOption("--refit-height", *args.refit_height);
  options.refit.lead = ParseCount("--refit-lead", args.refit_lead, 0);
  options.refit.min_samples = ParseCount("--refit-min-samples", args.refit_min_samples, 2);
  options.jobs = Jobs(args.jobs);
  options.spread = ClusterSpread();
  SetThreadsPerRank(options.jobs);
  return options;
}

uint64_t ParseSeed(const std::string& text) {
  const std::optional<long> seed = ParseWholeNumber(text, 0, 4294967295L);
  if (!seed) Refuse("--seed", text, "must be a whole number in [0, 4294967295]");
  return static_cast<uint64_t>(*seed);
}

MeasuredData DataOf(const ReplayArgs& args) {
  return args.measured ? *args.measured : ReadData("--data", args.data);
}

MeasuredData ReadData(const std::string& option, const std::string& path) {
  if (path.empty()) Refuse(option, path, "must name a trajectory file");
  return ReadMeasuredData(path);
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
