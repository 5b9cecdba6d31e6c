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

#include "scene/tags.h"

namespace contactlaws::cli {
namespace {

// "--max-timestep" -> "max_timestep".
std::string KeyOf(std::string_view option) {
  if (option.substr(0, 2) == "--") option.remove_prefix(2);
  std::string key(option);
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

}  // namespace

std::optional<app::Value> ValueOf(const std::optional<std::string>& text) {
  if (!text) return std::nullopt;
  return app::Value(*text);
}

std::string FlagSpelling(std::string_view key) { return kCommandLineSpelling.name(key); }

const app::OptionReader& Flags() {
  static const app::OptionReader flags(kCommandLineSpelling);
  return flags;
}

app::CommonInput InputOf(const CommonArgs& args) {
  app::CommonInput input;
  input.duration = args.duration;
  input.timestep = ValueOf(args.timestep);
  input.max_timestep = ValueOf(args.max_timestep);
  input.accuracy = ValueOf(args.accuracy);
  input.integrator = args.integrator;
  input.sample_rate = args.sample_rate;
  input.columns = args.columns;
  input.dissipation = ValueOf(args.dissipation);
  input.friction = args.friction;
  input.mu = ValueOf(args.mu);
  input.settle = args.settle;
  input.contact_steps = ValueOf(args.contact_steps);
  return input;
}

void Refuse(std::string_view option, std::string_view value, std::string_view requirement) {
  throw Error(fmt::format("{}={} {}", option, value, requirement));
}

double ParseOption(std::string_view option, std::string_view text) {
  return Flags().Number(KeyOf(option), std::string(text));
}

double ParsePositive(std::string_view option, std::string_view text, std::string_view unit) {
  return Flags().Positive(KeyOf(option), std::string(text), unit);
}

int ParseIntegrator(std::string_view name) { return Flags().Integrator(name); }

ColumnGroups ParseColumns(std::string_view text) { return Flags().Columns(text); }

double ParseAccuracy(const std::string& text, const std::optional<std::string>& timestep) {
  return Flags().Accuracy(text, ValueOf(timestep));
}

CommonOptions ParseCommon(const CommonArgs& args) { return Flags().Common(InputOf(args)); }

int ParseContactStepsOption(const std::string& text) { return Flags().ContactSteps(text); }

void ParseFrictionOverrides(const std::optional<std::string>& friction,
                            const std::optional<std::string>& mu, Overrides* overrides) {
  Flags().FrictionOverrides(friction, ValueOf(mu), overrides);
}

void ParseLawOverrides(const std::optional<std::string>& law,
                       const std::optional<std::string>& restitution, Overrides* overrides) {
  Flags().LawOverrides(law, ValueOf(restitution), overrides);
}

LawId ParseLaw(std::string_view option, std::string_view name) {
  return Flags().Law(KeyOf(option), name);
}

std::vector<LawId> ParseLawList(std::string_view option, std::string_view text) {
  return Flags().LawList(KeyOf(option), text);
}

std::vector<FrictionKind> ParseFrictionList(std::string_view option, std::string_view text) {
  return Flags().FrictionList(KeyOf(option), text);
}

double ParseDissipation(std::string_view text) { return Flags().Dissipation(std::string(text)); }

double ParseRestitution(std::string_view option, std::string_view text) {
  return Flags().Restitution(KeyOf(option), std::string(text));
}

std::vector<double> ParseRestitutionList(std::string_view option, std::string_view text) {
  return Flags().RestitutionList(KeyOf(option), std::string(text));
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
