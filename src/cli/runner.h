// Copyright contactlaws authors.
//
// What every command does with a scene: load it once, make a simulation per
// (law, restitution), step it to the end while sampling the trajectory on a
// fixed grid, and turn its impact log into CSV fields.

#ifndef CONTACTLAWS_CLI_RUNNER_H_
#define CONTACTLAWS_CLI_RUNNER_H_

#include <functional>
#include <memory>
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
};

// Steps sim from its current time until options.duration (or the first
// episode's end), calling on_row with Simulation::Sample() at every time
// k / sample_rate on the way, t = 0 included.
void Advance(Simulation* sim, const AdvanceOptions& options,
             const std::function<void(const std::vector<double>&)>& on_row);

// The impact-log CSV: its columns, and the fields of one impact.
std::vector<std::string> ImpactColumns();
std::vector<std::string> ImpactFields(const Simulation& sim, const Impact& impact);

// A number in its shortest exact form; an empty field for nullopt.
std::string Field(double value);
std::string Field(const std::optional<double>& value);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_RUNNER_H_
