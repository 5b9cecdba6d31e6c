// Copyright contactlaws authors.

#include "app/options.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include <fmt/format.h>

#include "laws/param_range.h"
#include "scene/number.h"
#include "scene/tags.h"

namespace contactlaws::app {
namespace {

// Longest restitution list a range may expand to.
constexpr long kMaxListLength = 100000;

// The most sub-steps contact_steps may ask for (ParseContactSteps' bound).
constexpr double kMaxContactSteps = 1e6;

std::vector<std::string_view> Split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  size_t start = 0;
  while (true) {
    const size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? end : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

double Round12(double v) { return std::round(v * 1e12) / 1e12; }

bool IsAuto(const Value& value) { return IsWord(value, "auto"); }

// The most runs at a time jobs takes (an int).
constexpr long kMaxJobs = 1L << 30;

// The column groups' words, in the order of the trajectory's column groups.
constexpr std::array<const char*, 5> kColumnGroupNames = {"bodies", "joints", "pairs", "friction",
                                                          "energy"};

// "bodies,joints,pairs,friction,energy" (any of them, no repeats) as
// ColumnGroups; nullopt, with the word at fault in *bad, for anything else.
std::optional<ColumnGroups> ParseColumnGroups(std::string_view text, std::string* bad) {
  ColumnGroups groups{false, false, false, false, false};
  const std::pair<const char*, bool ColumnGroups::*> names[] = {
      {kColumnGroupNames[0], &ColumnGroups::bodies},
      {kColumnGroupNames[1], &ColumnGroups::joints},
      {kColumnGroupNames[2], &ColumnGroups::pairs},
      {kColumnGroupNames[3], &ColumnGroups::friction},
      {kColumnGroupNames[4], &ColumnGroups::energy}};
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string_view word = text.substr(start, end - start);
    auto found = std::find_if(std::begin(names), std::end(names),
                              [&](const auto& n) { return word == n.first; });
    if (found == std::end(names) || groups.*found->second) {
      *bad = std::string(word);
      return std::nullopt;
    }
    groups.*found->second = true;
    start = end + 1;
  }
  return groups;
}

}  // namespace

std::string Shown(const Value& value) {
  if (const double* v = std::get_if<double>(&value)) return fmt::format("{}", *v);
  if (const auto* list = std::get_if<std::vector<double>>(&value)) {
    return fmt::format("{}", fmt::join(*list, ","));
  }
  return std::get<std::string>(value);
}

std::optional<double> NumberOf(const Value& value) {
  if (const double* v = std::get_if<double>(&value)) {
    if (!std::isfinite(*v)) return std::nullopt;
    return *v;
  }
  if (const std::string* text = std::get_if<std::string>(&value)) return ParseNumber(*text);
  return std::nullopt;
}

std::optional<long> WholeNumberOf(const Value& value, long lo, long hi) {
  const std::optional<double> number = NumberOf(value);
  if (!number || *number != std::floor(*number) || *number < lo || *number > hi) {
    return std::nullopt;
  }
  return static_cast<long>(*number);
}

bool IsWord(const Value& value, std::string_view word) {
  const std::string* text = std::get_if<std::string>(&value);
  return text && *text == word;
}

int DefaultJobs() {
  const unsigned cores = std::thread::hardware_concurrency();
  return cores > 0 ? static_cast<int>(cores) : 1;
}


void OptionReader::Refuse(std::string_view key, std::string_view value,
                          std::string_view requirement) const {
  throw Error(fmt::format("{}={} {}", Name(key), value, requirement));
}

double OptionReader::Number(std::string_view key, const Value& value) const {
  if (std::holds_alternative<std::vector<double>>(value)) {
    Refuse(key, Shown(value), "must be one number, not a list");
  }
  const std::optional<double> number = NumberOf(value);
  if (!number) Refuse(key, Shown(value), "is not a finite number");
  return *number;
}

double OptionReader::Positive(std::string_view key, const Value& value,
                              std::string_view unit) const {
  const double number = Number(key, value);
  if (!(number > 0)) {
    Refuse(key, fmt::format("{}", number), fmt::format("must be a number > 0 ({})", unit));
  }
  return number;
}

int OptionReader::Jobs(const std::optional<Value>& jobs) const {
  if (!jobs) return DefaultJobs();
  const std::optional<long> n = WholeNumberOf(*jobs, 1, kMaxJobs);
  if (!n) Refuse("jobs", Shown(*jobs), "must be a whole number >= 1");
  return static_cast<int>(*n);
}

int OptionReader::Integrator(std::string_view name) const {
  if (name == "euler") return mjINT_EULER;
  if (name == "rk4") return mjINT_RK4;
  if (name == "implicit") return mjINT_IMPLICIT;
  Refuse("integrator", name, "must be euler, rk4 or implicit");
}

ColumnGroups OptionReader::Columns(std::string_view text) const {
  std::string bad;
  const std::optional<ColumnGroups> groups = ParseColumnGroups(text, &bad);
  if (groups) return *groups;
  const bool known = std::find(kColumnGroupNames.begin(), kColumnGroupNames.end(), bad) !=
                     kColumnGroupNames.end();
  Refuse("columns", text,
         known ? fmt::format("names {} twice", bad)
               : fmt::format("has '{}', which is not a group ({})", bad,
                             fmt::join(kColumnGroupNames, ", ")));
}

double OptionReader::Accuracy(const Value& accuracy, const std::optional<Value>& timestep) const {
  const std::optional<double> value = NumberOf(accuracy);
  if (!value || !(*value > 0 && *value <= kMaxAccuracy)) {
    Refuse("accuracy", value ? fmt::format("{}", *value) : Shown(accuracy),
           fmt::format("must be a number in (0, {}] (relative error)", kMaxAccuracy));
  }
  if (timestep && !IsAuto(*timestep)) {
    Refuse("accuracy", fmt::format("{}", *value),
           fmt::format("goes with {}, not with the fixed {}={}", Given("timestep", "auto"),
                       Name("timestep"), Shown(*timestep)));
  }
  return *value;
}

CommonOptions OptionReader::Common(const CommonInput& input) const {
  CommonOptions options;
  options.duration = Positive("duration", input.duration, "s");
  options.sample_rate = Positive("sample_rate", input.sample_rate, "rows per simulated second");
  // accuracy alone asks for the auto timestep; with a fixed one it is refused
  const bool fixed = input.timestep && !IsAuto(*input.timestep);
  const bool auto_timestep = (input.timestep && !fixed) || (!input.timestep && input.accuracy);
  if (fixed) {
    if (!NumberOf(*input.timestep)) {
      Refuse("timestep", Shown(*input.timestep), "must be a number > 0 (s) or auto");
    }
    options.simulation.timestep = Positive("timestep", *input.timestep, "s");
  }
  if (input.max_timestep && !auto_timestep) {
    const std::optional<double> value = NumberOf(*input.max_timestep);
    Refuse("max_timestep", value ? fmt::format("{}", *value) : Shown(*input.max_timestep),
           fmt::format("goes with {}", Given("timestep", "auto")));
  }
  if (input.accuracy) Accuracy(*input.accuracy, input.timestep);
  if (auto_timestep) {
    options.auto_timestep.emplace();
    if (input.max_timestep) {
      options.auto_timestep->max_step = Positive("max_timestep", *input.max_timestep, "s");
    }
    if (input.accuracy) options.auto_timestep->accuracy = Accuracy(*input.accuracy, input.timestep);
  }
  if (input.integrator) options.simulation.integrator = Integrator(*input.integrator);
  if (input.contact_steps) {
    if (auto_timestep) {
      Refuse("contact_steps", Shown(*input.contact_steps), "goes with a fixed timestep");
    }
    options.simulation.contact_steps.substeps = ContactSteps(*input.contact_steps);
  }
  options.simulation.settle = input.settle;
  if (input.columns) options.simulation.columns = Columns(*input.columns);
  if (input.dissipation) options.simulation.overrides.dissipation = Dissipation(*input.dissipation);
  FrictionOverrides(input.friction, input.mu, &options.simulation.overrides);
  return options;
}

int OptionReader::ContactSteps(const Value& value) const {
  std::optional<int> substeps;
  if (const double* v = std::get_if<double>(&value)) {
    // a number by the rule of its text (ParseContactSteps)
    if (*v >= 1 && *v == std::floor(*v) && *v <= kMaxContactSteps) {
      substeps = static_cast<int>(*v);
    }
  } else if (const std::string* text = std::get_if<std::string>(&value)) {
    substeps = ParseContactSteps(*text);
  }
  if (!substeps) Refuse("contact_steps", Shown(value), kContactStepsRequirement);
  return *substeps;
}

void OptionReader::FrictionOverrides(const std::optional<std::string>& friction,
                                     const std::optional<Value>& mu, Overrides* overrides) const {
  if (friction) {
    overrides->friction = ParseFrictionName(*friction);
    if (!overrides->friction) {
      Refuse("friction", *friction,
             fmt::format("is not a friction model ({}){}", FrictionNameList(),
                         FrictionSuggestion(*friction)));
    }
  }
  if (mu) {
    const double value = Number("mu", *mu);
    if (!kNonNegativeRange.Contains(value)) {
      Refuse("mu", fmt::format("{}", value), kNonNegativeRange.Requirement());
    }
    overrides->mu = value;
  }
}

void OptionReader::LawOverrides(const std::optional<std::string>& law,
                                const std::optional<Value>& restitution,
                                Overrides* overrides) const {
  if (law) overrides->law = Law("law", *law);
  if (restitution) overrides->restitution = Restitution("restitution", *restitution);
}

LawId OptionReader::Law(std::string_view key, std::string_view name) const {
  const std::optional<LawId> law = ParseLawName(name);
  if (!law) {
    Refuse(key, name, fmt::format("is not a law ({}){}", LawNameList(), LawSuggestion(name)));
  }
  return *law;
}

namespace {

// Names separated by commas, each read by parse (nullopt: not `what`, one of
// `names`, with suggest's hint), none twice; "all" is every one, all.
template <typename Kind>
std::vector<Kind> ParseNameList(const OptionReader& reader, std::string_view key,
                                std::string_view text, std::string_view what,
                                const std::string& names, const std::vector<Kind>& all,
                                std::optional<Kind> (*parse)(std::string_view),
                                std::string (*suggest)(std::string_view)) {
  if (text == "all") return all;
  std::vector<Kind> kinds;
  for (std::string_view name : Split(text, ',')) {
    const std::optional<Kind> kind = parse(name);
    if (!kind) {
      reader.Refuse(key, text, fmt::format("has '{}', which is not {} (all, {}){}", name, what,
                                           names, suggest(name)));
    }
    if (std::find(kinds.begin(), kinds.end(), *kind) != kinds.end()) {
      reader.Refuse(key, text, fmt::format("names {} twice", name));
    }
    kinds.push_back(*kind);
  }
  return kinds;
}

}  // namespace

std::vector<LawId> OptionReader::LawList(std::string_view key, std::string_view text) const {
  return ParseNameList(*this, key, text, "a law", LawNameList(), AllLaws(), &ParseLawName,
                       &LawSuggestion);
}

std::vector<FrictionKind> OptionReader::FrictionList(std::string_view key,
                                                     std::string_view text) const {
  std::vector<FrictionKind> all;
  for (const FrictionInfo& model : FrictionModels()) all.push_back(model.kind);
  return ParseNameList(*this, key, text, "a friction model", FrictionNameList(), all,
                       &ParseFrictionName, &FrictionSuggestion);
}

double OptionReader::Dissipation(const Value& value) const {
  const double number = Number("dissipation", value);
  if (!kNonNegativeRange.Contains(number)) {
    Refuse("dissipation", fmt::format("{}", number), kNonNegativeRange.Requirement("s/m"));
  }
  return number;
}

double OptionReader::Restitution(std::string_view key, const Value& value) const {
  const double number = Number(key, value);
  if (!kUnitRange.Contains(number)) {
    Refuse(key, fmt::format("{}", number), kUnitRange.Requirement());
  }
  return number;
}

std::vector<double> OptionReader::RestitutionList(std::string_view key, const Value& value) const {
  const std::string text = Shown(value);
  // a list item or a range bound: a finite number, or Refuse
  const auto number = [&](std::string_view item) {
    const std::optional<double> v = ParseNumber(item);
    if (!v) Refuse(key, text, fmt::format("has '{}', which is not a finite number", item));
    return *v;
  };
  std::vector<double> values;
  const std::vector<std::string_view> range = Split(text, ':');
  if (std::holds_alternative<double>(value) ||
      std::holds_alternative<std::vector<double>>(value)) {
    values = std::holds_alternative<double>(value) ? std::vector<double>{std::get<double>(value)}
                                                   : std::get<std::vector<double>>(value);
    for (const double v : values) {
      if (!std::isfinite(v)) {
        Refuse(key, text, fmt::format("has '{}', which is not a finite number", v));
      }
    }
  } else if (range.size() == 3) {
    const double start = number(range[0]);
    const double stop = number(range[1]);
    const double step = number(range[2]);
    if (!(step > 0)) Refuse(key, text, "must have a step > 0 (start:stop:step)");
    if (stop < start) Refuse(key, text, "must have start <= stop (start:stop:step)");
    const double count = std::floor((stop - start) / step + 1e-9) + 1;
    if (count > kMaxListLength) {
      Refuse(key, text, fmt::format("expands to more than {} values", kMaxListLength));
    }
    for (long i = 0; i < static_cast<long>(count); ++i) values.push_back(Round12(start + i * step));
  } else if (range.size() == 1) {
    for (std::string_view item : Split(text, ',')) values.push_back(number(item));
  } else {
    Refuse(key, text, "must be E1,E2,... or start:stop:step");
  }
  for (size_t i = 0; i < values.size(); ++i) {
    if (!kUnitRange.Contains(values[i])) {
      Refuse(key, text, fmt::format("has {}, outside {}", values[i], kUnitRange.bounds));
    }
    if (std::find(values.begin(), values.begin() + i, values[i]) != values.begin() + i) {
      Refuse(key, text, fmt::format("has {} twice", values[i]));
    }
  }
  return values;
}

}  // namespace contactlaws::app
