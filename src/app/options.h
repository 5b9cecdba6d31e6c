// Copyright contactlaws authors.
//
// The options users give the work of the application (run, compare,
// restitution, check, laws, Simulation), read and validated once for both
// front-ends. An option is named by a key ("max_timestep"); each front-end
// spells it its own way in the messages (the command line "--max-timestep",
// Python "max_timestep"), by the Spelling it gives the reader. Each refusal
// is an Error "OPTION=VALUE REQUIREMENT", OPTION spelled.

#ifndef CONTACTLAWS_APP_OPTIONS_H_
#define CONTACTLAWS_APP_OPTIONS_H_

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "contactlaws/contactlaws.h"
#include "sim/spelling.h"

namespace contactlaws::app {

// How a front-end names an option in its messages (sim/spelling.h).
using contactlaws::kKeywordSpelling;
using contactlaws::Spelling;

// An option's value as a front-end has it: a number already (Python's float
// or int), text read by the option's grammar ("auto", "0.1:0.9:0.1",
// "1e-3"), or numbers already (Python's list of them, where the option
// takes a list). Numbers are held to the same rule as their text; a message
// shows them as "E1,E2,...".
using Value = std::variant<double, std::string, std::vector<double>>;

// A value as a message shows it: text as given, a number in its shortest
// exact form (fmt's "{}"), numbers so separated by commas.
std::string Shown(const Value& value);

// The number of value: itself when finite, or its text read by the one
// number parser (scene/number.h); nullopt otherwise (a list too).
std::optional<double> NumberOf(const Value& value);

// The value when it is a whole number in [lo, hi] (as ParseWholeNumber
// reads text), else nullopt.
std::optional<long> WholeNumberOf(const Value& value, long lo, long hi);

// Whether value is the word (text, not a number).
bool IsWord(const Value& value, std::string_view word);

// The number of runs at a time when none is asked for: the cores the
// machine reports.
int DefaultJobs();

// The restitutions of `laws` (text), and of `laws --format csv` when none are
// given.
inline constexpr char kDefaultRestitutions[] = "0.9,0.7,0.5,0.3,0.1";

// The options of run, compare, restitution and check as given.
struct CommonInput {
  Value duration = 2.0;                  // s
  std::optional<Value> timestep;         // a number > 0 (s), or "auto"
  std::optional<Value> max_timestep;     // s, with auto
  std::optional<Value> accuracy;         // auto's relative error; implies auto
  std::optional<std::string> integrator;  // euler, rk4, implicit
  Value sample_rate = 1000.0;            // rows per simulated second
  std::optional<std::string> columns;    // trajectory column groups
  std::optional<Value> dissipation;      // c (s/m) of the laws that read it
  std::optional<std::string> friction;   // every tagged pair's friction model
  std::optional<Value> mu;               // every tagged pair's mu (static = kinetic)
  bool settle = false;  // the bodies in contact at t = 0 into their static equilibrium
  std::optional<Value> contact_steps;    // "auto" or a count of sub-steps
};

// What SimulationOptions leave out of the common options: the run's length
// and sampling, and the auto timestep when asked for.
struct CommonOptions {
  SimulationOptions simulation;
  double duration = 0;     // s
  double sample_rate = 0;  // rows per simulated second
  std::optional<AutoTimestepOptions> auto_timestep;
};

// The grammar of the options, its messages in one front-end's spelling.
class OptionReader {
 public:
  explicit OptionReader(Spelling spelling) : spelling_(spelling) {}

  // The option of key as the front-end names it (Spelling).
  std::string Name(std::string_view key) const { return spelling_.name(key); }
  std::string Given(std::string_view key, std::string_view word) const {
    return spelling_.given(key, word);
  }
  std::string Set(std::string_view key) const { return spelling_.set(key); }
  const Spelling& spelling() const { return spelling_; }

  // Throws Error "OPTION=VALUE REQUIREMENT".
  [[noreturn]] void Refuse(std::string_view key, std::string_view value,
                           std::string_view requirement) const;

  // f(), its Error said of the option that gave what it refused: "OPTION:
  // MESSAGE" (the library names the key, value and range; the front-end its
  // option).
  template <typename F>
  auto UnderOption(std::string_view key, const F& f) const -> decltype(f()) {
    try {
      return f();
    } catch (const Error& e) {
      throw Error(Name(key) + ": " + e.what());
    }
  }

  // A finite number, or Refuse: "OPTION=VALUE is not a finite number".
  double Number(std::string_view key, const Value& value) const;

  // A number > 0, or Refuse: "OPTION=VALUE must be a number > 0 (UNIT)".
  double Positive(std::string_view key, const Value& value, std::string_view unit) const;

  // "bodies,joints,pairs,friction,energy" or any of them: the trajectory's
  // column groups.
  ColumnGroups Columns(std::string_view text) const;

  // accuracy: a number in (0, kMaxAccuracy], or Refuse; refused too beside
  // a fixed timestep (the timestep given, if any).
  double Accuracy(const Value& accuracy, const std::optional<Value>& timestep) const;

  // Validates the common options (overrides but dissipation left empty; no
  // timestep for auto).
  CommonOptions Common(const CommonInput& input) const;

  // contact_steps: "auto" (kContactStepsAuto) or a whole number >= 1 of
  // sub-steps, or Refuse.
  int ContactSteps(const Value& value) const;

  // jobs: DefaultJobs() when absent, else a whole number >= 1.
  int Jobs(const std::optional<Value>& jobs) const;

  // "euler", "rk4", "implicit" -> mjtIntegrator.
  int Integrator(std::string_view name) const;

  // law and restitution, when given, into overrides.
  void LawOverrides(const std::optional<std::string>& law, const std::optional<Value>& restitution,
                    Overrides* overrides) const;

  // A law name, or Refuse under key.
  LawId Law(std::string_view key, std::string_view name) const;

  // "all" (every law, in table order) or "L1,L2,..." (no repeats).
  std::vector<LawId> LawList(std::string_view key, std::string_view text) const;

  // friction MODEL and mu X into overrides (either may be absent).
  void FrictionOverrides(const std::optional<std::string>& friction,
                         const std::optional<Value>& mu, Overrides* overrides) const;

  // "all" (every friction model, in table order) or "M1,M2,..." (no repeats).
  std::vector<FrictionKind> FrictionList(std::string_view key, std::string_view text) const;

  // dissipation: a number >= 0 (s/m).
  double Dissipation(const Value& value) const;

  // A restitution in [0, 1].
  double Restitution(std::string_view key, const Value& value) const;

  // "E1,E2,..." or "start:stop:step" (stop included when it is on the grid,
  // to 1e-9 of a step), one number, or numbers. Values are rounded to 12 decimals, so
  // 0.1:1.0:0.1 gives exactly the doubles 0.1, 0.2, ..., 1. Each in [0, 1];
  // no repeats.
  std::vector<double> RestitutionList(std::string_view key, const Value& value) const;

 private:
  Spelling spelling_;
};

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_OPTIONS_H_
