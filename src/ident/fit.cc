// Copyright contactlaws authors.

#include "contactlaws/fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <nlopt.h>

#include "contactlaws/error.h"
#include "scene/number.h"
#include "scene/tag_keys.h"
#include "scene/tags.h"

namespace contactlaws {

namespace {

// The model parameters: name after the dot, what it edits, whether it names
// a body (else a geom, else nothing), and its range.
struct ModelKey {
  std::string_view name;
  ModelEdit::Kind kind;
  mjtObj object;  // mjOBJ_BODY, mjOBJ_GEOM, or mjOBJ_UNKNOWN for mujoco.*
  double min;     // the smallest value allowed
  bool min_open;  // min itself excluded
  double max;
  std::string_view range;  // for messages
};

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr ModelKey kModelKeys[] = {
    {"mass_scale", ModelEdit::Kind::kMassScale, mjOBJ_BODY, 0, true, kInf, "> 0"},
    {"inertia_scale", ModelEdit::Kind::kInertiaScale, mjOBJ_BODY, 0, true, kInf, "> 0"},
    {"offset", ModelEdit::Kind::kOffset, mjOBJ_GEOM, -kInf, false, kInf, "finite (m)"},
    {"timeconst", ModelEdit::Kind::kMujocoTimeconst, mjOBJ_UNKNOWN, 0, true, kInf, "> 0 (s)"},
    {"dampratio", ModelEdit::Kind::kMujocoDampratio, mjOBJ_UNKNOWN, 0, true, kInf, "> 0"},
    {"dmin", ModelEdit::Kind::kMujocoDmin, mjOBJ_UNKNOWN, 0, true, 1, "in (0, 1)"},
    {"dmax", ModelEdit::Kind::kMujocoDmax, mjOBJ_UNKNOWN, 0, true, 1, "in (0, 1)"},
    {"width", ModelEdit::Kind::kMujocoWidth, mjOBJ_UNKNOWN, 0, true, kInf, "> 0 (m)"},
    {"friction", ModelEdit::Kind::kMujocoFriction, mjOBJ_UNKNOWN, 0, false, kInf, ">= 0"},
};

bool InRange(const ModelKey& k, double v) {
  return (k.min_open ? v > k.min : v >= k.min) && (k.max == kInf ? v < kInf : v < k.max);
}

}  // namespace

double FitParameter::At(double u) const {
  if (log) return std::exp(std::log(lo) + u * (std::log(hi) - std::log(lo)));
  return lo + u * (hi - lo);
}

std::vector<FitParameter> ParseFitParameters(std::string_view text, const mjModel* m) {
  std::vector<FitParameter> parameters;
  auto fail = [](std::string_view item, std::string_view what) -> void {
    throw Error(fmt::format("--params: {}: {}", item, what));
  };
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = text.find(',', start);
    const std::string_view item = text.substr(start, comma - start);
    start = comma == std::string_view::npos ? text.size() + 1 : comma + 1;
    const size_t eq = item.find('=');
    if (eq == std::string_view::npos || eq == 0) {
      fail(item, "is not of the form KEY=LO:HI or KEY=LO:HI:log");
    }
    FitParameter p;
    p.key = std::string(item.substr(0, eq));
    // LO:HI[:log]
    std::string_view bounds = item.substr(eq + 1);
    std::vector<std::string_view> parts;
    for (size_t s = 0;;) {
      const size_t colon = bounds.find(':', s);
      parts.push_back(bounds.substr(s, colon - s));
      if (colon == std::string_view::npos) break;
      s = colon + 1;
    }
    if (parts.size() < 2 || parts.size() > 3 || (parts.size() == 3 && parts[2] != "log")) {
      fail(item, "bounds must be LO:HI or LO:HI:log");
    }
    const std::optional<double> lo = ParseNumber(parts[0]);
    const std::optional<double> hi = ParseNumber(parts[1]);
    if (!lo || !hi) fail(item, fmt::format("'{}' is not a finite number", !lo ? parts[0] : parts[1]));
    p.lo = *lo;
    p.hi = *hi;
    p.log = parts.size() == 3;
    if (!(p.lo < p.hi)) fail(item, fmt::format("the bounds are empty ({} >= {})", p.lo, p.hi));
    if (p.log && !(p.lo > 0)) fail(item, fmt::format("a log scale needs LO > 0, not {}", p.lo));
    for (const FitParameter& q : parameters) {
      if (q.key == p.key) fail(item, fmt::format("key '{}' is given twice", p.key));
    }

    const size_t dot = p.key.rfind('.');
    if (dot == std::string::npos) {
      // a tag key
      const TagKey* key = FindTagKey(p.key);
      if (!key) {
        const std::vector<std::string_view>& names = TagKeyNames();
        const std::string_view hint = NearestWord(p.key, names.data(), names.size());
        fail(item, fmt::format("'{}' is not a contactlaw tag key{}, nor OBJECT.KEY (mass_scale, "
                               "inertia_scale, offset, mujoco.*)",
                               p.key, hint.empty() ? "" : fmt::format(" (did you mean '{}'?)", hint)));
      }
      if (key->value != TagValue::kNumber) {
        fail(item, fmt::format("'{}' is not a numeric key (--laws and --frictions choose laws and "
                               "friction models)",
                               p.key));
      }
      parameters.push_back(std::move(p));
      continue;
    }
    const std::string object = p.key.substr(0, dot);
    const std::string_view name = std::string_view(p.key).substr(dot + 1);
    const ModelKey* key = nullptr;
    for (const ModelKey& k : kModelKeys) {
      if (k.name == name && (k.object == mjOBJ_UNKNOWN) == (object == "mujoco")) key = &k;
    }
    if (!key) {
      fail(item, fmt::format("'{}' is not a model parameter: BODY.mass_scale, BODY.inertia_scale, "
                             "GEOM.offset, mujoco.timeconst|dampratio|dmin|dmax|width|friction",
                             p.key));
    }
    p.tag_key = false;
    p.edit.kind = key->kind;
    if (key->object != mjOBJ_UNKNOWN) {
      p.edit.id = mj_name2id(m, key->object, object.c_str());
      if (p.edit.id < 0 || (key->object == mjOBJ_BODY && p.edit.id == 0)) {
        fail(item, fmt::format("the scene has no {} '{}'",
                               key->object == mjOBJ_BODY ? "moving body" : "geom", object));
      }
    }
    if (!InRange(*key, p.lo) || !InRange(*key, p.hi)) {
      fail(item, fmt::format("{} must be {}", name, key->range));
    }
    parameters.push_back(std::move(p));
  }
  if (parameters.empty()) throw Error("--params: no parameter given");
  return parameters;
}

ReplayOptions WithParameters(const ReplayOptions& options,
                             const std::vector<FitParameter>& parameters,
                             const std::vector<double>& values) {
  ReplayOptions out = options;
  for (size_t i = 0; i < parameters.size(); ++i) {
    const FitParameter& p = parameters[i];
    if (p.tag_key) {
      // 17 significant digits: the tag parser reads back the same double
      out.simulation.overrides.keys.emplace_back(p.key, fmt::format("{:.17g}", values[i]));
    } else {
      ModelEdit edit = p.edit;
      edit.value = values[i];
      out.edits.push_back(edit);
    }
  }
  return out;
}

namespace {

// Each tag's law and friction model as written, with the overrides: read
// without the fit's parameters, whose keys another law may refuse.
std::vector<std::pair<LawId, FrictionKind>> TagKinds(const Scene& scene, const Overrides& o) {
  const mjModel* m = scene.model();
  std::vector<std::pair<LawId, FrictionKind>> tags;
  for (int i = 0; i < m->ntext; ++i) {
    const std::string_view name = m->names + m->name_textadr[i];
    if (name.rfind(kPairTagPrefix, 0) != 0) continue;
    const internal::PairTagSpec spec = internal::ParsePairTag(scene.path(), name, m->text_data + m->text_adr[i]);
    tags.emplace_back(o.law.value_or(*spec.law),
                      o.friction.value_or(spec.friction.kind.value_or(FrictionKind::kCoulomb)));
  }
  return tags;
}

}  // namespace

std::string CombinationName(const Scene& scene, const Overrides& overrides) {
  const auto tags = TagKinds(scene, overrides);
  if (tags.empty()) return "mujoco";
  return fmt::format("{}/{}", LawName(tags[0].first), FrictionName(tags[0].second));
}

std::vector<bool> ParametersRead(const Scene& scene, const ReplayOptions& options,
                                 const std::vector<FitParameter>& parameters) {
  const auto tags = TagKinds(scene, options.simulation.overrides);
  std::vector<bool> read;
  for (const FitParameter& p : parameters) {
    bool any = !p.tag_key;
    const TagKey* key = p.tag_key ? FindTagKey(p.key) : nullptr;
    for (const auto& [law, friction] : tags) any = any || Reads(*key, law, friction);
    read.push_back(any);
  }
  return read;
}

void CheckFit(const Scene& scene, const ReplayOptions& options,
              const std::vector<FitParameter>& parameters) {
  std::vector<double> mid;
  for (const FitParameter& p : parameters) mid.push_back(p.At(0.5));
  auto make = [&](const std::vector<double>& values) {
    const ReplayOptions o = WithParameters(options, parameters, values);
    UniqueModel model(mj_copyModel(nullptr, scene.model()));
    ApplyEdits(model.get(), o.edits);
    return std::make_unique<ContactModel>(model.get(), scene.path(), o.simulation.overrides);
  };
  const std::vector<bool> read = ParametersRead(scene, options, parameters);
  for (size_t i = 0; i < parameters.size(); ++i) {
    if (read[i]) continue;
    std::string laws;
    for (const auto& [law, friction] : TagKinds(scene, options.simulation.overrides)) {
      laws += fmt::format("{}law={}, friction={}", laws.empty() ? "" : "; ", LawName(law),
                          FrictionName(friction));
    }
    throw Error(fmt::format("--params: {}: no tag of {} reads it ({})", parameters[i].key,
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
        throw Error(fmt::format("--params: {}={}:{}: the bound {} is refused: {}", parameters[i].key,
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

namespace {

// What the NLopt objective sees.
struct Objective {
  const Replay* replay;
  const FitOptions* options;
  nlopt_opt opt = nullptr;
  FitResult* result;
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
  for (unsigned i = 0; i < n; ++i) o->values[i] = options.parameters[i].At(std::clamp(u[i], 0.0, 1.0));
  const std::vector<ReplayedTrajectory> replayed =
      o->replay->Run(WithParameters(options.replay, options.parameters, o->values));
  for (const ReplayedTrajectory& r : replayed) {
    if (r.status == ReplayedTrajectory::Status::kInterrupted) {
      o->result->interrupted = true;
      if (o->opt) nlopt_force_stop(o->opt);
      return std::numeric_limits<double>::infinity();
    }
  }
  const double score = MeanScore(replayed, options.metric);
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
  FitResult result;
  Objective objective{&replay, &options, nullptr, &result, {}};
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
  std::vector<double> u(n, 0.5);
  Minimize(NLOPT_GN_CRS2_LM, global, &u, &objective);
  if (!result.interrupted && result.evaluations < options.budget && !result.values.empty()) {
    for (size_t i = 0; i < n; ++i) {
      const FitParameter& p = options.parameters[i];
      u[i] = p.log ? std::log(result.values[i] / p.lo) / std::log(p.hi / p.lo)
                   : (result.values[i] - p.lo) / (p.hi - p.lo);
    }
    // BOBYQA needs two parameters at least; COBYLA does with one
    Minimize(n >= 2 ? NLOPT_LN_BOBYQA : NLOPT_LN_COBYLA, options.budget - result.evaluations, &u,
             &objective);
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace contactlaws
