// Copyright contactlaws authors.

#include "app/identify_options.h"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "app/score_text.h"
#include "scene/number.h"
#include "scene/tags.h"

namespace contactlaws::app {
namespace {

// The most points of a profile: a best point and a neighbour each side at
// least; each point is a replay of every trajectory.
constexpr long kMinProfilePoints = 3;
constexpr long kMaxProfilePoints = 200;

// The most evaluations and samples a count takes.
constexpr long kMaxCount = 1000000;

// "P,A" or "P,A,J", each >= 0.
ScoreWeights ReadWeights(const OptionReader& reader, const std::string& text) {
  std::vector<double> w;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = text.find(',', start);
    const std::string part = text.substr(start, comma - start);
    const std::optional<double> v = ParseNumber(part);
    if (!v || *v < 0) reader.Refuse("weights", text, "must be P,A or P,A,J: numbers >= 0");
    w.push_back(*v);
    start = comma == std::string::npos ? text.size() + 1 : comma + 1;
  }
  if (w.size() < 2 || w.size() > 3) {
    reader.Refuse("weights", text, "must be P,A or P,A,J: numbers >= 0");
  }
  return {w[0], w[1], w.size() == 3 ? w[2] : 0.0};
}

int ReadCount(const OptionReader& reader, std::string_view key, const Value& value, long lo) {
  const std::optional<long> v = WholeNumberOf(value, lo, kMaxCount);
  if (!v) {
    reader.Refuse(key, Shown(value),
                  fmt::format("must be a whole number in [{}, {}]", lo, kMaxCount));
  }
  return static_cast<int>(*v);
}

// "restitution, mu": the keys of parameters.
std::string KeyList(const std::vector<FitParameter>& parameters) {
  std::string keys;
  for (const FitParameter& p : parameters) keys += (keys.empty() ? "" : ", ") + p.key;
  return keys;
}

// nullopt without profile. Refuses (one line, under its option) a key not in
// params, a key named twice, profile_points outside [3, 200], profile_budget
// outside [1, 1000000], either of them without profile.
std::optional<ProfileRequest> ReadProfile(const OptionReader& reader, const FitInput& input,
                                          const std::vector<FitParameter>& parameters,
                                          uint64_t seed) {
  if (!input.profile) {
    if (input.profile_points) {
      reader.Refuse("profile_points", Shown(*input.profile_points),
                    fmt::format("goes with {}", reader.Name("profile")));
    }
    if (input.profile_budget) {
      reader.Refuse("profile_budget", Shown(*input.profile_budget),
                    fmt::format("goes with {}", reader.Name("profile")));
    }
    return std::nullopt;
  }
  ProfileRequest request;
  request.options.seed = seed;
  const std::string& text = *input.profile;
  if (text == "all") {
    for (size_t i = 0; i < parameters.size(); ++i) request.keys.push_back(i);
  } else {
    size_t start = 0;
    while (start <= text.size()) {
      const size_t comma = text.find(',', start);
      const std::string key = text.substr(start, comma - start);
      const auto named = std::find_if(parameters.begin(), parameters.end(),
                                      [&](const FitParameter& p) { return p.key == key; });
      if (named == parameters.end()) {
        reader.Refuse("profile", text,
                      fmt::format("has '{}', which is not a key of {} ({}) nor all", key,
                                  reader.Name("params"), KeyList(parameters)));
      }
      const size_t place = named - parameters.begin();
      if (std::find(request.keys.begin(), request.keys.end(), place) != request.keys.end()) {
        reader.Refuse("profile", text, fmt::format("names {} twice", key));
      }
      request.keys.push_back(place);
      start = comma == std::string::npos ? text.size() + 1 : comma + 1;
    }
  }
  if (input.profile_points) {
    const std::optional<long> points =
        WholeNumberOf(*input.profile_points, kMinProfilePoints, kMaxProfilePoints);
    if (!points) {
      reader.Refuse("profile_points", Shown(*input.profile_points),
                    fmt::format("must be a whole number in [{}, {}]", kMinProfilePoints,
                                kMaxProfilePoints));
    }
    request.options.points = static_cast<int>(*points);
  }
  if (input.profile_budget) {
    request.options.budget = ReadCount(reader, "profile_budget", *input.profile_budget, 1);
  }
  return request;
}

// params' GEOM.offset=rest items, bounded by their estimates: text is params
// with each of them as GEOM.offset=0:1, a placeholder range that
// ParseFitParameters checks like any other (the key, the geom, a model
// edit), and bounds the estimates' intervals by key, set on the parsed
// parameters as numbers (SetRestBounds); lines: what each says, to print.
struct RestOffsets {
  std::string text;
  std::vector<std::pair<std::string, Interval>> bounds;
};

RestOffsets WithRestOffsets(const OptionReader& reader, const std::string& params,
                            const Scene& scene, const MeasuredData& data, uint64_t seed,
                            std::vector<std::string>* lines) {
  constexpr std::string_view kSuffix = ".offset=rest";
  RestOffsets out;
  size_t start = 0;
  while (start <= params.size()) {
    const size_t comma = params.find(',', start);
    std::string item = params.substr(start, comma - start);
    if (item.size() > kSuffix.size() &&
        item.compare(item.size() - kSuffix.size(), kSuffix.size(), kSuffix) == 0) {
      const std::string geom = item.substr(0, item.size() - kSuffix.size());
      try {
        const OffsetEstimate e = EstimateOffset(scene, geom, data, seed);
        if (!(e.interval.lo < e.interval.hi)) {
          throw Error(fmt::format("the interval [{}, {}] m is empty: nothing to fit within",
                                  e.interval.lo, e.interval.hi));
        }
        lines->push_back(OffsetText(geom, e) + ": fitted within that interval");
        out.bounds.emplace_back(geom + ".offset", e.interval);
        item = geom + ".offset=0:1";
      } catch (const Error& error) {
        throw Error(fmt::format("{}: {}: {}", reader.Name("params"), item, error.what()));
      }
    }
    out.text += (out.text.empty() ? "" : ",") + item;
    start = comma == std::string::npos ? params.size() + 1 : comma + 1;
  }
  return out;
}

// parameters' ranges set to offsets' bounds (a key's interval, exactly).
void SetRestBounds(const RestOffsets& offsets, std::vector<FitParameter>* parameters) {
  for (const auto& [key, interval] : offsets.bounds) {
    for (FitParameter& p : *parameters) {
      if (p.key == key) p.lo = interval.lo, p.hi = interval.hi;
    }
  }
}

}  // namespace

ReplayOptions ReadReplayOptions(const OptionReader& reader, const ReplayInput& input,
                                const Scene& scene, Metric* metric) {
  ReplayOptions options;
  const std::optional<Metric> m = ParseMetric(input.metric);
  if (!m) reader.Refuse("metric", input.metric, "must be e_q, position_rms, angle_rms or weighted");
  *metric = *m;
  if (input.weights && *m != Metric::kWeighted) {
    reader.Refuse("weights", *input.weights,
                  fmt::format("goes with {}", reader.Given("metric", "weighted")));
  }
  if (input.weights) options.weights = ReadWeights(reader, *input.weights);
  if (input.length) options.length = reader.Positive("length", *input.length, "m");
  const CommonOptions common = reader.Common(input);
  options.simulation = common.simulation;
  // the laws need the contact-aware step; MuJoCo's own contact its scene's
  bool tagged = false;
  for (int i = 0; i < scene.model()->ntext; ++i) {
    const char* name = scene.model()->names + scene.model()->name_textadr[i];
    tagged = tagged || std::string_view(name).rfind(kPairTagPrefix, 0) == 0;
  }
  options.auto_timestep = common.auto_timestep;
  if (!input.timestep && !options.auto_timestep && tagged) options.auto_timestep.emplace();
  reader.LawOverrides(input.law, input.restitution, &options.simulation.overrides);
  for (const std::string& word : input.set) {
    const size_t eq = word.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == word.size()) {
      reader.Refuse("set", word, "must be KEY=VALUE, a contactlaw tag key and its value");
    }
    options.simulation.overrides.keys.emplace_back(word.substr(0, eq), word.substr(eq + 1));
  }
  if (input.start == "refit") {
    options.start = StartRule::kRefit;
  } else if (input.start != "first") {
    reader.Refuse("start", input.start, "must be first or refit");
  }
  if (input.refit_height) options.refit.height = reader.Number("refit_height", *input.refit_height);
  options.refit.lead = ReadCount(reader, "refit_lead", input.refit_lead, 0);
  options.refit.min_samples = ReadCount(reader, "refit_min_samples", input.refit_min_samples, 2);
  options.jobs = reader.Jobs(input.jobs);
  return options;
}

uint64_t ReadSeed(const OptionReader& reader, const Value& seed) {
  const std::optional<long> n = WholeNumberOf(seed, 0, 4294967295L);
  if (!n) reader.Refuse("seed", Shown(seed), "must be a whole number in [0, 4294967295]");
  return static_cast<uint64_t>(*n);
}

MeasuredData ReadData(const OptionReader& reader, std::string_view key, const std::string& path) {
  if (path.empty()) reader.Refuse(key, path, "must name a trajectory file");
  return ReadMeasuredData(path);
}

FitRequest ReadFitRequest(const OptionReader& reader, const FitInput& input, const Scene& scene,
                          const MeasuredData& train_data, std::vector<std::string>* offset_lines) {
  FitRequest request;
  request.base = ReadReplayOptions(reader, input, scene, &request.metric);
  request.seed = ReadSeed(reader, input.seed);
  const uint64_t seed = request.seed;
  const RestOffsets rest =
      WithRestOffsets(reader, input.params, scene, train_data, seed, offset_lines);
  request.parameters = reader.UnderOption(
      "params", [&] { return ParseFitParameters(rest.text, scene.model()); });
  SetRestBounds(rest, &request.parameters);
  if (input.initial) {
    request.initial = reader.UnderOption("initial", [&] {
      return ParseFitInitial(*input.initial, request.parameters, scene.model());
    });
  }
  request.profile = ReadProfile(reader, input, request.parameters, seed);
  request.budget = ReadCount(reader, "budget", input.budget, 1);
  const int count = static_cast<int>(train_data.trajectories.size());
  if (input.folds) {
    const std::optional<long> folds = WholeNumberOf(*input.folds, 2, count);
    if (!folds) {
      reader.Refuse("folds", Shown(*input.folds),
                    fmt::format("must be a whole number in [2, {}] (the trajectories of {})",
                                count, train_data.source));
    }
    request.folds = static_cast<int>(*folds);
  }
  if (input.trim) {
    const std::optional<double> t = NumberOf(*input.trim);
    if (!t || !(*t >= 0 && *t < 0.5)) {
      reader.Refuse("trim", Shown(*input.trim), "must be a number in [0, 0.5)");
    }
    request.trim = *t;
  }
  if (input.laws) {
    request.laws.clear();
    for (LawId law : reader.LawList("laws", *input.laws)) request.laws.emplace_back(law);
  }
  if (input.frictions) {
    if (input.friction) {
      reader.Refuse("frictions", *input.frictions,
                    fmt::format("goes without {}", reader.Name("friction")));
    }
    request.frictions.clear();
    for (FrictionKind f : reader.FrictionList("frictions", *input.frictions)) {
      request.frictions.emplace_back(f);
    }
  }
  return request;
}

FitJob CheckedFitJob(const OptionReader& reader, const Scene& scene, const MeasuredData& train,
                     const MeasuredData* validate, FitRequest request) {
  return reader.UnderOption("params",
                            [&] { return FitJob(scene, train, validate, std::move(request)); });
}

}  // namespace contactlaws::app
