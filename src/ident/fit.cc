// Copyright contactlaws authors.

#include "contactlaws/fit.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include <fmt/format.h>
#include <nlopt.h>

#include "contactlaws/contact_model.h"
#include "contactlaws/replay.h"
#include "scene/parsed_tags.h"
#include "scene/tag_keys.h"

namespace contactlaws {

namespace {

// Each tag's law and friction model as written (the scene's tags, read
// once), with the overrides: without the fit's parameters, whose keys
// another law may refuse.
std::vector<Combination> TagKinds(const Scene& scene, const Overrides& o) {
  std::vector<Combination> tags;
  for (const auto& tag : internal::TagsOf(scene).pairs()) {
    if (!tag.error.empty()) throw Error(tag.error);
    internal::CheckPairTag(scene.path(), tag.name, tag.spec);
    const internal::PairTagSpec& spec = tag.spec;
    tags.push_back({o.law.value_or(*spec.law),
                    o.friction.value_or(spec.friction.kind.value_or(FrictionKind::kCoulomb))});
  }
  return tags;
}

}  // namespace

std::optional<Combination> FirstCombination(const Scene& scene, const Overrides& overrides) {
  const std::vector<Combination> tags = TagKinds(scene, overrides);
  if (tags.empty()) return std::nullopt;
  return tags.front();
}

std::string CombinationName(const Scene& scene, const Overrides& overrides) {
  const std::optional<Combination> first = FirstCombination(scene, overrides);
  if (!first) return "mujoco";
  return fmt::format("{}/{}", LawName(first->law), FrictionName(first->friction));
}

std::vector<bool> ParametersRead(const Scene& scene, const ReplayOptions& options,
                                 const std::vector<FitParameter>& parameters) {
  const auto tags = TagKinds(scene, options.simulation.overrides);
  std::vector<bool> read;
  for (const FitParameter& p : parameters) {
    bool any = !p.tag_key;
    const TagKey* key = p.tag_key ? FindTagKey(p.key) : nullptr;
    for (const Combination& tag : tags) any = any || Reads(*key, tag.law, tag.friction);
    read.push_back(any);
  }
  return read;
}

void CheckFit(const Scene& scene, const ReplayOptions& options,
              const std::vector<FitParameter>& parameters) {
  std::vector<double> mid;
  for (const FitParameter& p : parameters) mid.push_back(p.At(0.5));
  // the scene's tags with the parameters at values, on the edited model
  auto make = [&](const std::vector<double>& values) {
    const ReplayOptions o = WithParameters(options, parameters, values);
    UniqueModel model(mj_copyModel(nullptr, scene.model()));
    ApplyEdits(model.get(), o.edits);
    SimulationOptions tags;
    tags.overrides = o.simulation.overrides;
    return scene.Make(tags, std::move(model));
  };
  const std::vector<bool> read = ParametersRead(scene, options, parameters);
  for (size_t i = 0; i < parameters.size(); ++i) {
    if (read[i]) continue;
    std::string laws;
    for (const Combination& tag : TagKinds(scene, options.simulation.overrides)) {
      laws += fmt::format("{}law={}, friction={}", laws.empty() ? "" : "; ", LawName(tag.law),
                          FrictionName(tag.friction));
    }
    throw Error(fmt::format("{}: no tag of {} reads it ({})", parameters[i].key,
                            scene.path(), laws));
  }
  for (size_t i = 0; i < parameters.size(); ++i) {
    if (!parameters[i].tag_key) continue;
    for (double bound : {parameters[i].lo, parameters[i].hi}) {
      std::vector<double> values = mid;
      values[i] = bound;
      try {
        make(values);
      } catch (const Error& e) {
        throw Error(fmt::format("{}={}:{}: the bound {} is refused: {}", parameters[i].key,
                                parameters[i].lo, parameters[i].hi, bound, e.what()));
      }
    }
  }
}

double MeanScore(const std::vector<ReplayedTrajectory>& replayed, Metric metric) {
  if (replayed.empty()) return 0;
  double sum = 0;
  for (const ReplayedTrajectory& r : replayed) sum += r.score.Of(metric);
  return sum / replayed.size();
}

double TrimmedMeanScore(const std::vector<ReplayedTrajectory>& replayed, Metric metric,
                        double trim) {
  if (trim == 0) return MeanScore(replayed, metric);
  std::vector<double> values;
  values.reserve(replayed.size());
  for (const ReplayedTrajectory& r : replayed) values.push_back(r.score.Of(metric));
  return TrimmedMean(std::move(values), trim);
}

namespace {

// What the NLopt objective sees.
struct Objective {
  const Replay* replay;
  const FitOptions* options;
  nlopt_opt opt = nullptr;
  FitResult* result;
  // the start, scaled and in units: at start_u, a parameter takes the start's
  // value itself, which At(start_u) may miss by a rounding
  std::vector<double> start_u, start;
  std::vector<double> values;  // scratch
};

double Evaluate(unsigned n, const double* u, double* /*gradient*/, void* data) {
  auto* o = static_cast<Objective*>(data);
  const FitOptions& options = *o->options;
  // spread over processes, a stop is seen through the statuses the replay
  // exchanges, so that every process stops at the same evaluation
  if (!options.replay.spread && options.replay.should_stop && options.replay.should_stop()) {
    o->result->interrupted = true;
    if (o->opt) nlopt_force_stop(o->opt);
    return std::numeric_limits<double>::infinity();
  }
  o->values.resize(n);
  for (unsigned i = 0; i < n; ++i) {
    o->values[i] = u[i] == o->start_u[i] ? o->start[i]
                                         : options.parameters[i].At(std::clamp(u[i], 0.0, 1.0));
  }
  const std::vector<ReplayedTrajectory> replayed =
      o->replay->Run(WithParameters(options.replay, options.parameters, o->values));
  for (const ReplayedTrajectory& r : replayed) {
    if (r.status == ReplayedTrajectory::Status::kInterrupted) {
      o->result->interrupted = true;
      if (o->opt) nlopt_force_stop(o->opt);
      return std::numeric_limits<double>::infinity();
    }
  }
  const double score = TrimmedMeanScore(replayed, options.metric, options.trim);
  FitResult& result = *o->result;
  ++result.evaluations;
  if (result.values.empty() || score < result.score) {
    result.score = score;
    result.values = o->values;
  }
  if (options.on_evaluation) options.on_evaluation(result.evaluations, score, result.score);
  return score;
}

// One NLopt run of algorithm from u over at most budget evaluations.
void Minimize(nlopt_algorithm algorithm, int budget, std::vector<double>* u, Objective* o) {
  const unsigned n = static_cast<unsigned>(u->size());
  nlopt_opt opt = nlopt_create(algorithm, n);
  o->opt = opt;
  const std::vector<double> lower(n, 0.0), upper(n, 1.0);
  nlopt_set_lower_bounds(opt, lower.data());
  nlopt_set_upper_bounds(opt, upper.data());
  nlopt_set_min_objective(opt, Evaluate, o);
  nlopt_set_maxeval(opt, budget);
  // a point within 1e-4 of the range is as good as found: the scores' own
  // scatter over a toss set is larger than what that resolves
  nlopt_set_xtol_abs1(opt, 1e-4);
  if (algorithm == NLOPT_GN_CRS2_LM) {
    // CRS2's population, 10 (n + 1) by default, cut so that the search
    // iterates at least twice its population's size within a small budget
    nlopt_set_population(opt, static_cast<unsigned>(std::clamp(budget / 3, static_cast<int>(n) + 2,
                                                               10 * (static_cast<int>(n) + 1))));
  } else {
    nlopt_set_initial_step1(opt, 0.05);
  }
  double best = 0;
  nlopt_optimize(opt, u->data(), &best);
  nlopt_destroy(opt);
  o->opt = nullptr;
}

}  // namespace

FitResult Fit(const Replay& replay, const FitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  CheckInitial(options.parameters, options.initial);
  if (!(options.trim >= 0 && options.trim < 0.5)) {
    throw Error(fmt::format("trim {}: must be in [0, 0.5)", options.trim));
  }
  FitResult result;
  Objective objective{&replay, &options, nullptr, &result, {}, {}, {}};
  const size_t n = options.parameters.size();
  // the global search's share; the local search polishes its best point
  const int global = std::max(static_cast<int>(0.7 * options.budget), 1);
  if (n == 0) {
    // nothing the tags read: the scores of the scene as it is
    Evaluate(0, nullptr, nullptr, &objective);
    result.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
  nlopt_srand(options.seed);
  // the start: CRS2 evaluates it first
  for (size_t i = 0; i < n; ++i) {
    const FitParameter& p = options.parameters[i];
    const bool given = !options.initial.empty() && options.initial[i];
    objective.start_u.push_back(given ? std::clamp(p.Unit(*options.initial[i]), 0.0, 1.0) : 0.5);
    objective.start.push_back(given ? *options.initial[i] : p.At(0.5));
  }
  std::vector<double> u = objective.start_u;
  Minimize(NLOPT_GN_CRS2_LM, global, &u, &objective);
  if (!result.interrupted && result.evaluations < options.budget && !result.values.empty()) {
    for (size_t i = 0; i < n; ++i) u[i] = options.parameters[i].Unit(result.values[i]);
    // BOBYQA needs two parameters at least; COBYLA does with one
    Minimize(n >= 2 ? NLOPT_LN_BOBYQA : NLOPT_LN_COBYLA, options.budget - result.evaluations, &u,
             &objective);
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace contactlaws
