// Copyright contactlaws authors.

#include "scene/tags.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"
#include "scene/number.h"
#include "scene/tag_keys.h"

namespace contactlaws {

using internal::FrictionTagSpec;
using internal::PairTagSpec;

namespace {

// key=value words of a tag's data, in order.
struct TagWord {
  std::string_view key;
  std::string_view value;
};

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
         c == '\f';
}

// Builds messages "SOURCE: TAG: ..." for one tag.
class TagContext {
 public:
  TagContext(std::string_view source, std::string_view name)
      : source_(source), name_(name) {}

  [[noreturn]] void Fail(std::string_view what) const {
    throw Error(fmt::format("{}: {}: {}", source_, name_, what));
  }

  [[noreturn]] void FailValue(std::string_view key, std::string_view value,
                              std::string_view requirement) const {
    Fail(fmt::format("{}={} {}", key, value, requirement));
  }

  // A key not in allowed, with the nearest as a hint.
  [[noreturn]] void FailUnknown(std::string_view key, const std::string_view* allowed,
                                size_t count) const {
    const std::string_view hint = NearestWord(key, allowed, count);
    Fail(hint.empty() ? fmt::format("unknown key '{}'", key)
                      : fmt::format("unknown key '{}' (did you mean '{}'?)", key, hint));
  }

  // Splits data into key=value words, refusing malformed and repeated keys
  // and keys not in allowed.
  std::vector<TagWord> Split(std::string_view data, const std::string_view* allowed,
                              size_t count) const {
    std::vector<TagWord> words;
    size_t i = 0;
    while (i < data.size()) {
      while (i < data.size() && IsSpace(data[i])) ++i;
      size_t start = i;
      while (i < data.size() && !IsSpace(data[i])) ++i;
      if (start == i) break;
      std::string_view word = data.substr(start, i - start);
      size_t eq = word.find('=');
      if (eq == std::string_view::npos || eq == 0) {
        Fail(fmt::format("'{}' is not of the form key=value", word));
      }
      TagWord kv{word.substr(0, eq), word.substr(eq + 1)};
      if (std::find(allowed, allowed + count, kv.key) == allowed + count) {
        FailUnknown(kv.key, allowed, count);
      }
      for (const TagWord& seen : words) {
        if (seen.key == kv.key) Fail(fmt::format("key '{}' is given twice", kv.key));
      }
      if (kv.value.empty()) FailValue(kv.key, "", "has no value");
      words.push_back(kv);
    }
    return words;
  }

  double Number(const TagWord& kv) const {
    std::optional<double> v = ParseNumber(kv.value);
    if (!v) FailValue(kv.key, kv.value, "is not a finite number");
    return *v;
  }

 private:
  std::string_view source_;
  std::string_view name_;
};

std::string_view Label(const TagContext& ctx, std::string_view name,
                       std::string_view prefix) {
  if (name.substr(0, prefix.size()) != prefix) {
    ctx.Fail(fmt::format("the tag name must start with '{}'", prefix));
  }
  std::string_view label = name.substr(prefix.size());
  if (label.empty()) ctx.Fail("the tag has an empty label");
  return label;
}

// The first friction key given, for the warning on a frictionless pair.
void NoteFrictionKey(const TagKey& key, PairTagSpec* spec) {
  if (key.friction_side() && spec->friction.first_key.empty()) {
    spec->friction.first_key = std::string(key.name);
  }
}

// A numeric key's value v into spec, refused outside the key's range; text
// is the value as the message shows it.
void SetNumber(const TagContext& ctx, const TagKey& key, double v, std::string_view text,
               PairTagSpec* spec) {
  if (!key.range->Contains(v)) ctx.FailValue(key.name, text, key.range->Requirement(key.unit));
  (key.number ? spec->*key.number : spec->friction.*key.friction_number) = v;
  NoteFrictionKey(key, spec);
}

// The value of one key of a contactlaw tag into spec, as its row says.
void ParseKey(const TagContext& ctx, const TagKey& key, const TagWord& kv, PairTagSpec* spec) {
  switch (key.value) {
    case TagValue::kGeom:
      spec->*key.text = std::string(kv.value);
      break;
    case TagValue::kLaw:
      spec->law = ParseLawName(kv.value);
      if (!spec->law) {
        ctx.FailValue(kv.key, kv.value,
                      fmt::format("is not a law ({}){}", LawNameList(), LawSuggestion(kv.value)));
      }
      break;
    case TagValue::kFriction:
      spec->friction.kind = ParseFrictionName(kv.value);
      if (!spec->friction.kind) {
        ctx.FailValue(kv.key, kv.value,
                      fmt::format("is not a friction model ({}){}", FrictionNameList(),
                                  FrictionSuggestion(kv.value)));
      }
      break;
    case TagValue::kSwitch:
      if (kv.value == "true" || kv.value == "1") {
        spec->allow_tension = true;
      } else if (kv.value == "false" || kv.value == "0") {
        spec->allow_tension = false;
      } else {
        ctx.FailValue(kv.key, kv.value, "must be true or false");
      }
      break;
    case TagValue::kNumber:
      SetNumber(ctx, key, ctx.Number(kv), kv.value, spec);
      return;
  }
  NoteFrictionKey(key, spec);
}

// Friction keys that exclude each other or disagree.
void CheckFrictionKeys(const TagContext& ctx, const FrictionTagSpec& f) {
  if (f.mu && (f.mu_static || f.mu_kinetic)) {
    ctx.Fail(fmt::format("mu={} and {} exclude each other (mu sets both)", *f.mu,
                         f.mu_static ? "mu_static" : "mu_kinetic"));
  }
  const bool both_k = f.tangential_stiffness && f.tangential_ratio;
  if (both_k || (f.tangential_damping && f.tangential_damping_ratio)) {
    ctx.Fail(both_k ? "tangential_stiffness and tangential_ratio exclude each other"
                    : "tangential_damping and tangential_damping_ratio exclude each other");
  }
  if (f.mu_static && f.mu_kinetic && *f.mu_kinetic > *f.mu_static) {
    ctx.FailValue("mu_kinetic", fmt::format("{}", *f.mu_kinetic),
                  fmt::format("must be in [0, mu_static={}]", *f.mu_static));
  }
}

}  // namespace

std::string WithKeys(std::string_view data,
                     const std::vector<std::pair<std::string, std::string>>& keys) {
  std::string out;
  std::vector<bool> placed(keys.size(), false);
  auto append = [&](std::string_view key, std::string_view value) {
    out.append(out.empty() ? "" : " ").append(key).append("=").append(value);
  };
  size_t i = 0;
  while (i < data.size()) {
    while (i < data.size() && IsSpace(data[i])) ++i;
    const size_t start = i;
    while (i < data.size() && !IsSpace(data[i])) ++i;
    if (start == i) break;
    const std::string_view word = data.substr(start, i - start);
    const size_t eq = word.find('=');
    const std::string_view key = word.substr(0, eq);
    // the last value given for the key, in the word's place
    std::optional<size_t> set;
    for (size_t k = 0; k < keys.size(); ++k) {
      if (keys[k].first == key) set = k;
    }
    if (!set) {
      out.append(out.empty() ? "" : " ").append(word);
    } else if (!placed[*set]) {
      append(key, keys[*set].second);
      for (size_t k = 0; k < keys.size(); ++k) placed[k] = placed[k] || keys[k].first == key;
    }
  }
  for (size_t k = 0; k < keys.size(); ++k) {
    if (placed[k]) continue;
    size_t last = k;  // the last value given for the key
    for (size_t j = k + 1; j < keys.size(); ++j) {
      if (keys[j].first == keys[k].first) last = j;
    }
    append(keys[k].first, keys[last].second);
    for (size_t j = k; j < keys.size(); ++j) placed[j] = placed[j] || keys[j].first == keys[k].first;
  }
  return out;
}

PairTagSpec internal::ParsePairTag(std::string_view source, std::string_view name,
                                   std::string_view data) {
  PairTagSpec spec = ParsePairWords(source, name, data);
  CheckPairTag(source, name, spec);
  return spec;
}

PairTagSpec internal::ParsePairWords(std::string_view source, std::string_view name,
                                     std::string_view data) {
  TagContext ctx(source, name);
  PairTagSpec spec;
  spec.label = std::string(Label(ctx, name, kPairTagPrefix));
  const std::vector<std::string_view>& names = TagKeyNames();
  for (const TagWord& kv : ctx.Split(data, names.data(), names.size())) {
    ParseKey(ctx, *FindTagKey(kv.key), kv, &spec);
  }
  return spec;
}

void internal::SetPairWord(std::string_view source, std::string_view name, std::string_view key,
                           std::string_view value, PairTagSpec* spec) {
  TagContext ctx(source, name);
  const std::vector<std::string_view>& names = TagKeyNames();
  const TagKey* row = FindTagKey(key);
  if (!row) ctx.FailUnknown(key, names.data(), names.size());
  if (value.empty()) ctx.FailValue(key, "", "has no value");
  ParseKey(ctx, *row, TagWord{key, value}, spec);
}

void internal::SetPairNumber(std::string_view source, std::string_view name, std::string_view key,
                             double value, PairTagSpec* spec) {
  TagContext ctx(source, name);
  const TagKey* row = FindTagKey(key);
  if (!row || row->value != TagValue::kNumber) {
    ctx.Fail(fmt::format("'{}' is not a numeric contactlaw tag key", key));
  }
  SetNumber(ctx, *row, value, fmt::format("{}", value), spec);
}

void internal::CheckPairTag(std::string_view source, std::string_view name,
                            const PairTagSpec& spec) {
  TagContext ctx(source, name);
  // keys every tag needs, and keys that go together
  if (spec.geom1.empty()) ctx.Fail("missing key geom1");
  if (spec.geom2.empty()) ctx.Fail("missing key geom2");
  if (!spec.law) ctx.Fail("missing key law");
  CheckFrictionKeys(ctx, spec.friction);
  // a key only some laws read, on a law that does not: it would be ignored
  for (const TagKey& key : TagKeys()) {
    if (!key.refused_unread || !(spec.*key.number) ||
        Reads(key, *spec.law, FrictionKind::kNone)) {
      continue;
    }
    ctx.Fail(fmt::format("{}={} is not read by law={}, which takes: {}", key.name,
                         *(spec.*key.number), LawName(*spec.law), Law(*spec.law).parameters));
  }
  const int materials = spec.youngs1.has_value() + spec.poisson1.has_value() +
                        spec.youngs2.has_value() + spec.poisson2.has_value();
  if (materials != 0 && materials != 4) {
    const char* missing = !spec.youngs1    ? "youngs1"
                          : !spec.poisson1 ? "poisson1"
                          : !spec.youngs2  ? "youngs2"
                                           : "poisson2";
    ctx.Fail(fmt::format("missing key {} (materials need youngs1 poisson1 youngs2 poisson2)",
                         missing));
  }
  if (materials == 4 && spec.stiffness) {
    ctx.Fail("stiffness and materials (youngs1 ...) exclude each other");
  }
}

DriveTagSpec ParseDriveTag(std::string_view source, std::string_view name,
                           std::string_view data) {
  TagContext ctx(source, name);
  DriveTagSpec spec;
  spec.label = std::string(Label(ctx, name, kDriveTagPrefix));
  bool has_amplitude = false;
  bool has_omega = false;
  bool has_speed = false;

  for (const TagWord& kv : ctx.Split(data, kDriveKeys.data(), kDriveKeys.size())) {
    const std::string_view k = kv.key;
    if (k == "body") {
      spec.body = std::string(kv.value);
    } else if (k == "motion") {
      if (kv.value != "sine" && kv.value != "linear") {
        ctx.FailValue(k, kv.value, "must be sine or linear");
      }
      spec.linear = kv.value == "linear";
    } else if (k == "speed") {
      spec.speed = ctx.Number(kv);
      has_speed = true;
    } else if (k == "axis") {
      if (kv.value == "x" || kv.value == "y" || kv.value == "z") {
        spec.axis = {0, 0, 0};
        spec.axis[kv.value[0] - 'x'] = 1;
      } else {
        // ax,ay,az
        std::array<double, 3> a{};
        std::string_view rest = kv.value;
        for (int i = 0; i < 3; ++i) {
          size_t comma = rest.find(',');
          std::string_view part = rest.substr(0, comma);
          std::optional<double> v = ParseNumber(part);
          if (!v || (i < 2) == (comma == std::string_view::npos)) {
            ctx.FailValue(k, kv.value, "must be x, y, z or ax,ay,az");
          }
          a[i] = *v;
          rest = comma == std::string_view::npos ? std::string_view()
                                                 : rest.substr(comma + 1);
        }
        double norm = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        if (!(norm > 0.0) || !std::isfinite(norm)) {
          ctx.FailValue(k, kv.value, "must be a nonzero vector");
        }
        spec.axis = {a[0] / norm, a[1] / norm, a[2] / norm};
      }
    } else if (k == "amplitude") {
      spec.amplitude = ctx.Number(kv);
      has_amplitude = true;
    } else if (k == "omega") {
      spec.omega = ctx.Number(kv);
      has_omega = true;
    } else if (k == "phase") {
      spec.phase = ctx.Number(kv);
    }
  }
  if (spec.body.empty()) ctx.Fail("missing key body");
  if (spec.linear) {
    // p(t) = pos + axis speed t: the sine's keys would be ignored
    if (!has_speed) ctx.Fail("missing key speed (m/s, a finite number) for motion=linear");
    if (has_amplitude || has_omega) {
      ctx.Fail(fmt::format("{} is not read by motion=linear, which takes: axis, speed (m/s)",
                           has_amplitude ? "amplitude" : "omega"));
    }
    return spec;
  }
  if (has_speed) ctx.Fail("speed is not read by motion=sine, which takes: axis, amplitude, omega, phase");
  if (!has_amplitude) ctx.Fail("missing key amplitude");
  if (!has_omega) ctx.Fail("missing key omega");
  return spec;
}

}  // namespace contactlaws
