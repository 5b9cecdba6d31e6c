// Copyright contactlaws authors.
//
// What every command does with a scene: load it once, make a simulation per
// (law, restitution), step it to the end while sampling the trajectory on a
// fixed grid, and turn its impact log into CSV fields.

#ifndef CONTACTLAWS_CLI_RUNNER_H_
#define CONTACTLAWS_CLI_RUNNER_H_

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contactlaws/contactlaws.h"

namespace contactlaws::cli {

// An MJCF scene, parsed once; every simulation gets its own copy of the model.
class Scene {
 public:
  explicit Scene(std::string path);  // throws Error "PATH: ..."
  // A model already loaded; name stands for its file in messages.
  Scene(std::string name, UniqueModel model);

  const std::string& path() const { return path_; }
  const mjModel* model() const { return model_.get(); }

  // A fresh simulation; throws Error when the tags (with the overrides) are
  // refused.
  std::unique_ptr<Simulation> Make(const SimulationOptions& options) const;

 private:
  std::string path_;
  UniqueModel model_;
};

// The restitution a run reports: its input e, and 1 for Hertz, which is
// elastic whatever e it was given (so long-format CSV can group on it).
double ReportedRestitution(LawKind law, double restitution);

struct AdvanceOptions {
  double duration = 2.0;     // s of simulated time
  double sample_rate = 0.0;  // rows per simulated second; 0: no rows
  // Stop as soon as the first contact episode of the scene's first tag ends.
  bool until_first_episode = false;
  // Step with AutoTimestep instead of the model's fixed timestep; rows stay
  // on the sample grid (steps are cut at sample times).
  std::optional<AutoTimestepOptions> auto_timestep;
};

// How a call of Advance ended.
struct AdvanceResult {
  enum class Status {
    kComplete,     // reached the duration (or the first episode's end)
    kDiverged,     // stopped at divergence (see divergence)
    kInterrupted,  // stopped because StopRequested()
  };
  Status status = Status::kComplete;
  std::optional<Divergence> divergence;
  // Set when the total energy of an undriven scene grew beyond
  // kEnergyGrowthTolerance: how much, and when it was largest.
  std::optional<std::string> energy_growth;
  // With the auto timestep: the steps taken, and those at a contact's fine step.
  long steps = 0;
  long fine_steps = 0;
};

// Steps sim from its current time until options.duration (or the first
// episode's end), calling on_row with Simulation::Sample() at every time
// k / sample_rate on the way, t = 0 included. Stops at divergence (the rows
// given so far are finite) and when a stop is requested. Checks the energy
// ledger of undriven scenes at every row and at the end.
AdvanceResult Advance(Simulation* sim, const AdvanceOptions& options,
                      const std::function<void(const std::vector<double>&)>& on_row);

// Asks every Advance in the process to stop after its current step (safe to
// call from a signal handler), and whether that was asked.
void RequestStop();
bool StopRequested();

// MuJoCo's messages to mju_user_warning. The program installs
// RecordMujocoWarning, which keeps them (thread-safe) instead of letting
// MuJoCo print to stdout, where CSV may go. Runs report their warnings from
// d->warning with counts and note them here; UnreportedMujocoWarnings gives
// the others (a model's, say), each once with the times it came.
void RecordMujocoWarning(const char* text);
void NoteReportedMujocoWarning(const std::string& text);
std::vector<MujocoWarning> UnreportedMujocoWarnings();

// Each tag's estimated contact at the simulation's current state, and how
// many steps of the scene's timestep resolve it.
struct TimestepAdvice {
  int tag = -1;
  TagEstimate shortest;
  double steps = 0;     // per estimated contact duration (inf: not estimated)
  bool coarse = false;  // steps < kStepsPerContact
};
std::vector<TimestepAdvice> AdviseTimestep(Simulation* sim);

// "contactlaw:TAG (g1, g2): timestep H s puts S steps in the estimated
// contact duration T s (>= 20 needed): use --timestep H' or smaller".
std::string CoarseTimestepWarning(const Simulation& sim, const TimestepAdvice& advice);

// "t = T s: contactlaw:TAG (g1, g2): depth D m, depth rate R m/s: WHAT;
// likely cause: ..." for a run stopped at divergence; advice from before the
// run names the timestep against the estimated contact duration.
std::string DivergenceMessage(const Simulation& sim, const Divergence& divergence,
                              const std::vector<TimestepAdvice>& advice);

// The impact-log CSV: its columns, and the fields of one impact.
std::vector<std::string> ImpactColumns();
std::vector<std::string> ImpactFields(const Simulation& sim, const Impact& impact);

// A number in its shortest exact form; an empty field for nullopt.
std::string Field(double value);
std::string Field(const std::optional<double>& value);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_RUNNER_H_
