// Copyright contactlaws authors.

#include "cli/options.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <optional>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "laws/param_range.h"
#include "scene/number.h"
#include "scene/tags.h"

namespace contactlaws::cli {
namespace {

// Longest restitution list a range may expand to.
constexpr long kMaxListLength = 100000;

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

// The whole of text as a finite number, or Refuse.
double Number(std::string_view option, std::string_view text, std::string_view whole) {
  const std::optional<double> value = ParseNumber(text);
  if (!value) Refuse(option, whole, fmt::format("has '{}', which is not a finite number", text));
  return *value;
}

double Round12(double v) { return std::round(v * 1e12) / 1e12; }

// --columns' words, in the order of the trajectory's column groups.
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

void Refuse(std::string_view option, std::string_view value, std::string_view requirement) {
  throw Error(fmt::format("{}={} {}", option, value, requirement));
}

double ParseOption(std::string_view option, std::string_view text) {
  const std::optional<double> value = ParseNumber(text);
  if (!value) Refuse(option, text, "is not a finite number");
  return *value;
}

double ParsePositive(std::string_view option, std::string_view text, std::string_view unit) {
  const double value = ParseOption(option, text);
  if (!(value > 0)) {
    Refuse(option, fmt::format("{}", value), fmt::format("must be a number > 0 ({})", unit));
  }
  return value;
}

int ParseIntegrator(std::string_view name) {
  if (name == "euler") return mjINT_EULER;
  if (name == "rk4") return mjINT_RK4;
  if (name == "implicit") return mjINT_IMPLICIT;
  Refuse("--integrator", name, "must be euler, rk4 or implicit");
}

ColumnGroups ParseColumns(std::string_view text) {
  std::string bad;
  const std::optional<ColumnGroups> groups = ParseColumnGroups(text, &bad);
  if (groups) return *groups;
  const bool known = std::find(kColumnGroupNames.begin(), kColumnGroupNames.end(), bad) !=
                     kColumnGroupNames.end();
  Refuse("--columns", text,
         known ? fmt::format("names {} twice", bad)
               : fmt::format("has '{}', which is not a group ({})", bad,
                             fmt::join(kColumnGroupNames, ", ")));
}

double ParseAccuracy(const std::string& text, const std::optional<std::string>& timestep) {
  const std::optional<double> value = ParseNumber(text);
  if (!value || !(*value > 0 && *value <= kMaxAccuracy)) {
    Refuse("--accuracy", value ? fmt::format("{}", *value) : text,
           fmt::format("must be a number in (0, {}] (relative error)", kMaxAccuracy));
  }
  if (timestep && *timestep != "auto") {
    Refuse("--accuracy", fmt::format("{}", *value),
           fmt::format("goes with --timestep auto, not with the fixed --timestep={}", *timestep));
  }
  return *value;
}

CommonOptions ParseCommon(const CommonArgs& args) {
  CommonOptions options;
  options.duration = ParsePositive("--duration", args.duration, "s");
  options.sample_rate = ParsePositive("--sample-rate", args.sample_rate, "rows per simulated second");
  // --accuracy alone asks for the auto timestep; with a fixed one it is refused
  const bool fixed = args.timestep && *args.timestep != "auto";
  const bool auto_timestep = (args.timestep && !fixed) || (!args.timestep && args.accuracy);
  if (fixed) {
    if (!ParseNumber(*args.timestep)) {
      Refuse("--timestep", *args.timestep, "must be a number > 0 (s) or auto");
    }
    options.simulation.timestep = ParsePositive("--timestep", *args.timestep, "s");
  }
  if (args.max_timestep && !auto_timestep) {
    const std::optional<double> value = ParseNumber(*args.max_timestep);
    Refuse("--max-timestep", value ? fmt::format("{}", *value) : *args.max_timestep,
           "goes with --timestep auto");
  }
  if (args.accuracy) ParseAccuracy(*args.accuracy, args.timestep);
  if (auto_timestep) {
    options.auto_timestep.emplace();
    if (args.max_timestep) {
      options.auto_timestep->max_step = ParsePositive("--max-timestep", *args.max_timestep, "s");
    }
    if (args.accuracy) options.auto_timestep->accuracy = ParseAccuracy(*args.accuracy, args.timestep);
  }
  if (args.integrator) options.simulation.integrator = ParseIntegrator(*args.integrator);
  if (args.contact_steps) {
    if (auto_timestep) Refuse("--contact-steps", *args.contact_steps, "goes with a fixed timestep");
    options.simulation.contact_steps.substeps = ParseContactStepsOption(*args.contact_steps);
  }
  options.simulation.settle = args.settle;
  if (args.columns) options.simulation.columns = ParseColumns(*args.columns);
  if (args.dissipation) {
    options.simulation.overrides.dissipation = ParseDissipation(*args.dissipation);
  }
  ParseFrictionOverrides(args.friction, args.mu, &options.simulation.overrides);
  return options;
}

int ParseContactStepsOption(const std::string& text) {
  const std::optional<int> substeps = ParseContactSteps(text);
  if (!substeps) Refuse("--contact-steps", text, kContactStepsRequirement);
  return *substeps;
}

void ParseFrictionOverrides(const std::optional<std::string>& friction,
                            const std::optional<std::string>& mu, Overrides* overrides) {
  if (friction) {
    overrides->friction = ParseFrictionName(*friction);
    if (!overrides->friction) {
      Refuse("--friction", *friction,
             fmt::format("is not a friction model ({}){}", FrictionNameList(),
                         FrictionSuggestion(*friction)));
    }
  }
  if (mu) {
    const double value = ParseOption("--mu", *mu);
    if (!kNonNegativeRange.Contains(value)) {
      Refuse("--mu", fmt::format("{}", value), kNonNegativeRange.Requirement());
    }
    overrides->mu = value;
  }
}

void ParseLawOverrides(const std::optional<std::string>& law,
                       const std::optional<std::string>& restitution, Overrides* overrides) {
  if (law) overrides->law = ParseLaw("--law", *law);
  if (restitution) overrides->restitution = ParseRestitution("--restitution", *restitution);
}

LawId ParseLaw(std::string_view option, std::string_view name) {
  const std::optional<LawId> law = ParseLawName(name);
  if (!law) {
    Refuse(option, name, fmt::format("is not a law ({}){}", LawNameList(), LawSuggestion(name)));
  }
  return *law;
}

namespace {

// Names separated by commas, each read by parse (nullopt: not `what`, one of
// `names`, with suggest's hint), none twice; "all" is every one, all.
template <typename Kind>
std::vector<Kind> ParseNameList(std::string_view option, std::string_view text,
                                std::string_view what, const std::string& names,
                                const std::vector<Kind>& all,
                                std::optional<Kind> (*parse)(std::string_view),
                                std::string (*suggest)(std::string_view)) {
  if (text == "all") return all;
  std::vector<Kind> kinds;
  for (std::string_view name : Split(text, ',')) {
    const std::optional<Kind> kind = parse(name);
    if (!kind) {
      Refuse(option, text, fmt::format("has '{}', which is not {} (all, {}){}", name, what,
                                       names, suggest(name)));
    }
    if (std::find(kinds.begin(), kinds.end(), *kind) != kinds.end()) {
      Refuse(option, text, fmt::format("names {} twice", name));
    }
    kinds.push_back(*kind);
  }
  return kinds;
}

}  // namespace

std::vector<LawId> ParseLawList(std::string_view option, std::string_view text) {
  return ParseNameList(option, text, "a law", LawNameList(), AllLaws(), &ParseLawName,
                       &LawSuggestion);
}

std::vector<FrictionKind> ParseFrictionList(std::string_view option, std::string_view text) {
  std::vector<FrictionKind> all;
  for (const FrictionInfo& model : FrictionModels()) all.push_back(model.kind);
  return ParseNameList(option, text, "a friction model", FrictionNameList(), all,
                       &ParseFrictionName, &FrictionSuggestion);
}

double ParseDissipation(std::string_view text) {
  const double value = ParseOption("--dissipation", text);
  if (!kNonNegativeRange.Contains(value)) {
    Refuse("--dissipation", fmt::format("{}", value), kNonNegativeRange.Requirement("s/m"));
  }
  return value;
}

double ParseRestitution(std::string_view option, std::string_view text) {
  const double value = ParseOption(option, text);
  if (!kUnitRange.Contains(value)) {
    Refuse(option, fmt::format("{}", value), kUnitRange.Requirement());
  }
  return value;
}

std::vector<double> ParseRestitutionList(std::string_view option, std::string_view text) {
  std::vector<double> values;
  const std::vector<std::string_view> range = Split(text, ':');
  if (range.size() == 3) {
    const double start = Number(option, range[0], text);
    const double stop = Number(option, range[1], text);
    const double step = Number(option, range[2], text);
    if (!(step > 0)) Refuse(option, text, "must have a step > 0 (start:stop:step)");
    if (stop < start) Refuse(option, text, "must have start <= stop (start:stop:step)");
    const double count = std::floor((stop - start) / step + 1e-9) + 1;
    if (count > kMaxListLength) {
      Refuse(option, text, fmt::format("expands to more than {} values", kMaxListLength));
    }
    for (long i = 0; i < static_cast<long>(count); ++i) values.push_back(Round12(start + i * step));
  } else if (range.size() == 1) {
    for (std::string_view item : Split(text, ',')) values.push_back(Number(option, item, text));
  } else {
    Refuse(option, text, "must be E1,E2,... or start:stop:step");
  }
  for (size_t i = 0; i < values.size(); ++i) {
    if (!kUnitRange.Contains(values[i])) {
      Refuse(option, text, fmt::format("has {}, outside {}", values[i], kUnitRange.bounds));
    }
    if (std::find(values.begin(), values.begin() + i, values[i]) != values.begin() + i) {
      Refuse(option, text, fmt::format("has {} twice", values[i]));
    }
  }
  return values;
}

CLI::Option* AddNumber(CLI::App* cmd, const std::string& name, std::string* value,
                       const std::string& help) {
  return cmd->add_option(name, *value, help)->type_name("FLOAT");
}
CLI::Option* AddNumber(CLI::App* cmd, const std::string& name,
                       std::optional<std::string>* value, const std::string& help) {
  return cmd->add_option(name, *value, help)->type_name("FLOAT");
}

void AddDissipation(CLI::App* cmd, std::optional<std::string>* dissipation) {
  AddNumber(cmd, "--dissipation", dissipation,
            "override every tag's dissipation c, s/m >= 0, for the laws that read it "
            "(hunt-crossley-constant); the others ignore it");
}

void AddSettle(CLI::App* cmd, bool* settle) {
  cmd->add_flag("--settle", *settle,
                "before t = 0, move the bodies that start in contact into the static equilibrium "
                "of their contacts (positions only); refused when there is none");
}

void AddFriction(CLI::App* cmd, std::optional<std::string>* friction,
                 std::optional<std::string>* mu) {
  cmd->add_option("--friction", *friction,
                  fmt::format("override every tagged pair's friction model: {}", FrictionNameList()));
  AddNumber(cmd, "--mu", mu,
            "override every tagged pair's friction coefficient (static = kinetic), >= 0");
}

void AddOverrides(CLI::App* cmd, std::optional<std::string>* law,
                  std::optional<std::string>* restitution) {
  cmd->add_option("--law", *law, fmt::format("override every tag's law: {}", LawNameList()));
  AddNumber(cmd, "--restitution", restitution, "override every tag's restitution e, in [0, 1]");
}

void AddCommon(CLI::App* cmd, CommonArgs* args, bool sampling) {
  cmd->add_option("scene", args->scene, "MJCF scene with contactlaw tags")->required();
  AddNumber(cmd, "--duration", &args->duration, "simulated time, s")->capture_default_str();
  cmd->add_option("--timestep", args->timestep,
                  "s (default: the scene's), or auto: long steps while the tagged pairs are "
                  "apart, steps that resolve the contact near and in it (docs/timestep.md)");
  AddNumber(cmd, "--max-timestep", &args->max_timestep,
            "s, with --timestep auto: an optional cap on every step (default: none)");
  AddNumber(cmd, "--accuracy", &args->accuracy,
            "with --timestep auto (implied): the relative error accepted in a collision's "
            "rebound, peak force and duration, in (0, 0.1] (default 0.001)");
  cmd->add_option("--integrator", args->integrator,
                  "euler, rk4 or implicit (default: the scene's)");
  AddDissipation(cmd, &args->dissipation);
  AddFriction(cmd, &args->friction, &args->mu);
  AddSettle(cmd, &args->settle);
  cmd->add_option("--contact-steps", args->contact_steps,
                  "auto or N: integrate the contacts inside each fixed step, in sub-steps per "
                  "contact (auto) or N of them, and apply their mean force (docs/timestep.md, "
                  "\"Contact steps\"); default: off");
  if (sampling) {
    AddNumber(cmd, "--sample-rate", &args->sample_rate, "trajectory rows per simulated second")
        ->capture_default_str();
    cmd->add_option("--columns", args->columns,
                    "trajectory column groups: any of bodies,joints,pairs,friction,energy "
                    "(default: all)");
  }
}

}  // namespace contactlaws::cli
