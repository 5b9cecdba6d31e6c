// Copyright contactlaws authors.
//
// A fit's parameters: parsed from their text (the command line's --params),
// mapped to [0, 1] and back, their start parsed (--initial), and set on
// replay options as values (contactlaws/fit.h).

#include "contactlaws/fit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"
#include "scene/number.h"
#include "scene/tag_keys.h"

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

// text's parts between separators ("" is one empty part).
std::vector<std::string_view> Split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  for (size_t s = 0;;) {
    const size_t at = text.find(separator, s);
    parts.push_back(text.substr(s, at - s));
    if (at == std::string_view::npos) return parts;
    s = at + 1;
  }
}

// p's key resolved: a numeric tag key, or a model parameter (p->tag_key
// false, p->edit's kind and object set, *model its row). Returns why it is
// neither, or "".
std::string ResolveKey(const mjModel* m, FitParameter* p, const ModelKey** model) {
  const size_t dot = p->key.rfind('.');
  if (dot == std::string::npos) {
    // a tag key
    const TagKey* key = FindTagKey(p->key);
    if (!key) {
      const std::vector<std::string_view>& names = TagKeyNames();
      const std::string_view hint = NearestWord(p->key, names.data(), names.size());
      return fmt::format("'{}' is not a contactlaw tag key{}, nor OBJECT.KEY (mass_scale, "
                         "inertia_scale, offset, mujoco.*)",
                         p->key, hint.empty() ? "" : fmt::format(" (did you mean '{}'?)", hint));
    }
    if (key->value != TagValue::kNumber) {
      return fmt::format("'{}' is not a numeric key (laws and friction models are compared, not "
                         "fitted)",
                         p->key);
    }
    return "";
  }
  const std::string object = p->key.substr(0, dot);
  const std::string_view name = std::string_view(p->key).substr(dot + 1);
  const ModelKey* key = nullptr;
  for (const ModelKey& k : kModelKeys) {
    if (k.name == name && (k.object == mjOBJ_UNKNOWN) == (object == "mujoco")) key = &k;
  }
  if (!key) {
    return fmt::format("'{}' is not a model parameter: BODY.mass_scale, BODY.inertia_scale, "
                       "GEOM.offset, mujoco.timeconst|dampratio|dmin|dmax|width|friction",
                       p->key);
  }
  p->tag_key = false;
  p->edit.kind = key->kind;
  if (key->object != mjOBJ_UNKNOWN) {
    p->edit.id = mj_name2id(m, key->object, object.c_str());
    if (p->edit.id < 0 || (key->object == mjOBJ_BODY && p->edit.id == 0)) {
      return fmt::format("the scene has no {} '{}'",
                         key->object == mjOBJ_BODY ? "moving body" : "geom", object);
    }
  }
  *model = key;
  return "";
}

// "restitution, stiffness": the parameters' keys.
std::string KeyList(const std::vector<FitParameter>& parameters) {
  std::string keys;
  for (const FitParameter& p : parameters) keys += (keys.empty() ? "" : ", ") + p.key;
  return keys;
}

}  // namespace

double FitParameter::At(double u) const {
  if (log) return std::exp(std::log(lo) + u * (std::log(hi) - std::log(lo)));
  return lo + u * (hi - lo);
}

double FitParameter::Unit(double value) const {
  return log ? std::log(value / lo) / std::log(hi / lo) : (value - lo) / (hi - lo);
}

std::vector<FitParameter> ParseFitParameters(std::string_view text, const mjModel* m) {
  std::vector<FitParameter> parameters;
  auto fail = [](std::string_view item, std::string_view what) -> void {
    throw Error(fmt::format("{}: {}", item, what));
  };
  for (const std::string_view item : Split(text, ',')) {
    const size_t eq = item.find('=');
    if (eq == std::string_view::npos || eq == 0) {
      fail(item, "is not of the form KEY=LO:HI or KEY=LO:HI:log");
    }
    FitParameter p;
    p.key = std::string(item.substr(0, eq));
    // LO:HI[:log]
    const std::vector<std::string_view> parts = Split(item.substr(eq + 1), ':');
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
    const ModelKey* model = nullptr;
    const std::string why = ResolveKey(m, &p, &model);
    if (!why.empty()) fail(item, why);
    if (model && (!InRange(*model, p.lo) || !InRange(*model, p.hi))) {
      fail(item, fmt::format("{} must be {}", model->name, model->range));
    }
    parameters.push_back(std::move(p));
  }
  if (parameters.empty()) throw Error("no parameter given");
  return parameters;
}

std::vector<std::optional<double>> ParseFitInitial(std::string_view text,
                                                   const std::vector<FitParameter>& parameters,
                                                   const mjModel* m) {
  std::vector<std::optional<double>> initial(parameters.size());
  auto fail = [](std::string_view item, std::string_view what) -> void {
    throw Error(fmt::format("{}: {}", item, what));
  };
  for (const std::string_view item : Split(text, ',')) {
    const size_t eq = item.find('=');
    if (eq == std::string_view::npos || eq == 0) fail(item, "is not of the form KEY=VALUE");
    FitParameter p;
    p.key = std::string(item.substr(0, eq));
    const auto named = std::find_if(parameters.begin(), parameters.end(),
                                    [&](const FitParameter& q) { return q.key == p.key; });
    if (named == parameters.end()) {
      const ModelKey* model = nullptr;
      const std::string why = ResolveKey(m, &p, &model);
      if (!why.empty()) fail(item, why);
      fail(item, fmt::format("'{}' is not one of the parameters ({})", p.key, KeyList(parameters)));
    }
    const std::optional<double> value = ParseNumber(item.substr(eq + 1));
    if (!value) fail(item, fmt::format("'{}' is not a finite number", item.substr(eq + 1)));
    std::optional<double>& slot = initial[named - parameters.begin()];
    if (slot) fail(item, fmt::format("key '{}' is given twice", p.key));
    slot = *value;
  }
  CheckInitial(parameters, initial);
  return initial;
}

void CheckInitial(const std::vector<FitParameter>& parameters,
                  const std::vector<std::optional<double>>& initial) {
  if (initial.empty()) return;
  if (initial.size() != parameters.size()) {
    throw Error(fmt::format("{} values given for {} parameters ({})", initial.size(),
                            parameters.size(), KeyList(parameters)));
  }
  for (size_t i = 0; i < parameters.size(); ++i) {
    const FitParameter& p = parameters[i];
    if (initial[i] && !(p.lo <= *initial[i] && *initial[i] <= p.hi)) {
      throw Error(fmt::format("{}={}: outside its bounds [{}, {}]", p.key, *initial[i],
                              p.lo, p.hi));
    }
  }
}

ReplayOptions WithParameters(const ReplayOptions& options,
                             const std::vector<FitParameter>& parameters,
                             const std::vector<double>& values) {
  ReplayOptions out = options;
  for (size_t i = 0; i < parameters.size(); ++i) {
    const FitParameter& p = parameters[i];
    if (p.tag_key) {
      out.simulation.overrides.values.push_back({p.key, values[i]});
    } else {
      ModelEdit edit = p.edit;
      edit.value = values[i];
      out.edits.push_back(edit);
    }
  }
  return out;
}

}  // namespace contactlaws
