// Copyright contactlaws authors.
//
// The command line's shared options, parsed and validated: each refusal is an
// Error whose message names the option, the value and what it must be.

#ifndef CONTACTLAWS_CLI_OPTIONS_H_
#define CONTACTLAWS_CLI_OPTIONS_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contactlaws/contactlaws.h"

namespace contactlaws::cli {

// The options of run, compare, restitution and check as given.
struct CommonArgs {
  std::string scene;
  double duration = 2.0;
  std::optional<std::string> timestep;  // a number, or "auto"
  std::optional<double> max_timestep;   // with auto
  std::optional<std::string> integrator;
  double sample_rate = 1000.0;
};

// Throws Error "OPTION=VALUE REQUIREMENT".
[[noreturn]] void Refuse(std::string_view option, std::string_view value,
                         std::string_view requirement);

// A finite number > 0, or Refuse naming option and unit.
void RequirePositive(std::string_view option, double value, std::string_view unit);

// Validates duration and sample rate; returns timestep and integrator as
// SimulationOptions (overrides left empty; no timestep for auto).
SimulationOptions ParseCommon(const CommonArgs& args);

// The auto timestep's options for --timestep auto (and --max-timestep);
// nullopt for a fixed timestep.
std::optional<AutoTimestepOptions> ParseAutoTimestep(const CommonArgs& args);

// "euler", "rk4", "implicit" -> mjtIntegrator.
int ParseIntegrator(std::string_view name);

// A law name, or Refuse under option.
LawKind ParseLaw(std::string_view option, std::string_view name);

// "all" (the five, in kAllLaws order) or "L1,L2,..." (no repeats).
std::vector<LawKind> ParseLawList(std::string_view option, std::string_view text);

// A restitution in [0, 1].
double ParseRestitution(std::string_view option, double value);

// "E1,E2,..." or "start:stop:step" (stop included when it is on the grid, to
// 1e-9 of a step). Values are rounded to 12 decimals, so 0.1:1.0:0.1 gives
// exactly the doubles 0.1, 0.2, ..., 1. Each in [0, 1]; no repeats.
std::vector<double> ParseRestitutionList(std::string_view option, std::string_view text);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_OPTIONS_H_
