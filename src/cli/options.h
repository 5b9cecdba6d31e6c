// Copyright contactlaws authors.
//
// The command line's shared options, declared to its parser (CLI11), parsed
// and validated: each refusal is an Error whose message names the option, the
// value and what it must be.

#ifndef CONTACTLAWS_CLI_OPTIONS_H_
#define CONTACTLAWS_CLI_OPTIONS_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/options.h"
#include "contactlaws/contactlaws.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace contactlaws::cli {

// The options of run, compare, restitution and check as given: numbers as
// text, read by the one number parser (scene/number.h) as tags are.
struct CommonArgs {
  std::string scene;
  std::string duration = "2";
  std::optional<std::string> timestep;  // a number, or "auto"
  std::optional<std::string> max_timestep;  // with auto
  std::optional<std::string> accuracy;  // auto's relative error; implies auto
  std::optional<std::string> integrator;
  std::string sample_rate = "1000";
  std::optional<std::string> columns;  // trajectory column groups
  std::optional<std::string> dissipation;  // c (s/m) of the laws that read it
  std::optional<std::string> friction;     // every tagged pair's friction model
  std::optional<std::string> mu;           // every tagged pair's mu (static = kinetic)
  bool settle = false;  // the bodies in contact at t = 0 into their static equilibrium
  std::optional<std::string> contact_steps;  // "auto" or a count of sub-steps
};

using app::CommonOptions;
using app::kDefaultRestitutions;

// The options' grammar (app/options.h) spelling each key as the command
// line's flag: "max_timestep" -> "--max-timestep", given a word "--timestep
// auto", a switch "--settle".
std::string FlagSpelling(std::string_view key);
const app::OptionReader& Flags();

// An option's text as the grammar takes it.
std::optional<app::Value> ValueOf(const std::optional<std::string>& text);

// The common options as the grammar takes them: the same text.
app::CommonInput InputOf(const CommonArgs& args);

// Throws Error "OPTION=VALUE REQUIREMENT".
[[noreturn]] void Refuse(std::string_view option, std::string_view value,
                         std::string_view requirement);

// f(), its Error said of the option that gave what it refused: "OPTION:
// MESSAGE" (the library names the key, value and range; the command line its
// flag).
template <typename F>
auto UnderOption(std::string_view option, const F& f) -> decltype(f()) {
  try {
    return f();
  } catch (const Error& e) {
    throw Error(std::string(option) + ": " + e.what());
  }
}

// The grammar's readers (app::OptionReader) under their flags: OPTION is
// the flag ("--mu"), each message word for word the grammar's.

// The number text, or Refuse: "OPTION=TEXT is not a finite number".
double ParseOption(std::string_view option, std::string_view text);

// A number > 0, or Refuse: "OPTION=VALUE must be a number > 0 (UNIT)".
double ParsePositive(std::string_view option, std::string_view text, std::string_view unit);

// --columns (OptionReader::Columns).
ColumnGroups ParseColumns(std::string_view text);

// --accuracy (OptionReader::Accuracy).
double ParseAccuracy(const std::string& text, const std::optional<std::string>& timestep);

// Validates the common options (OptionReader::Common).
CommonOptions ParseCommon(const CommonArgs& args);

// --contact-steps (OptionReader::ContactSteps).
int ParseContactStepsOption(const std::string& text);

// --integrator (OptionReader::Integrator).
int ParseIntegrator(std::string_view name);

// --law and --restitution, when given, into overrides.
void ParseLawOverrides(const std::optional<std::string>& law,
                       const std::optional<std::string>& restitution, Overrides* overrides);

// A law name, or Refuse under option.
LawId ParseLaw(std::string_view option, std::string_view name);

// "all" (every law, in table order) or "L1,L2,..." (no repeats).
std::vector<LawId> ParseLawList(std::string_view option, std::string_view text);

// --friction MODEL and --mu X into overrides (either may be absent).
void ParseFrictionOverrides(const std::optional<std::string>& friction,
                            const std::optional<std::string>& mu, Overrides* overrides);

// "all" (every friction model, in table order) or "M1,M2,..." (no repeats).
std::vector<FrictionKind> ParseFrictionList(std::string_view option, std::string_view text);

// --dissipation: a number >= 0 (s/m).
double ParseDissipation(std::string_view text);

// A restitution in [0, 1].
double ParseRestitution(std::string_view option, std::string_view text);

// OptionReader::RestitutionList of the text.
std::vector<double> ParseRestitutionList(std::string_view option, std::string_view text);

// The shared options declared to the command line (CLI11), each into its
// field of the *Args above as text; a command's own are in main.cc.

// A number option: taken as text, read by the one number parser (the
// Parse* functions), shown as FLOAT in the help.
CLI::Option* AddNumber(CLI::App* cmd, const std::string& name, std::string* value,
                       const std::string& help);
CLI::Option* AddNumber(CLI::App* cmd, const std::string& name,
                       std::optional<std::string>* value, const std::string& help);

// --dissipation (ParseDissipation).
void AddDissipation(CLI::App* cmd, std::optional<std::string>* dissipation);

// --settle.
void AddSettle(CLI::App* cmd, bool* settle);

// --friction and --mu (ParseFrictionOverrides).
void AddFriction(CLI::App* cmd, std::optional<std::string>* friction,
                 std::optional<std::string>* mu);

// --law and --restitution (ParseLawOverrides).
void AddOverrides(CLI::App* cmd, std::optional<std::string>* law,
                  std::optional<std::string>* restitution);

// CommonArgs: the scene and the options ParseCommon reads, with
// --sample-rate and --columns when sampling.
void AddCommon(CLI::App* cmd, CommonArgs* args, bool sampling);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_OPTIONS_H_
