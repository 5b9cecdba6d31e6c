// Copyright contactlaws authors.
//
// The stepping loop of a Simulation with its monitors: divergence after every
// step, the energy ledger of an undriven scene, the run's stop flag (a
// program's Ctrl-C), and the trajectory sampled on a fixed grid. What the command line, the
// benchmarks and a user's program step with.

#ifndef CONTACTLAWS_ADVANCE_H_
#define CONTACTLAWS_ADVANCE_H_

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "contactlaws/auto_timestep.h"
#include "contactlaws/impact.h"
#include "contactlaws/simulation.h"

namespace contactlaws {

struct AdvanceOptions {
  double duration = 2.0;     // s of simulated time
  double sample_rate = 0.0;  // rows per simulated second; 0: no rows
  // Stop as soon as the first contact episode of the scene's first tag ends.
  bool until_first_episode = false;
  // Step with AutoTimestep instead of the model's fixed timestep; rows stay
  // on the sample grid: a row inside a step is interpolated between the
  // step's exact ends (src/sim/dense_rows.h), a row at a step's end is its.
  std::optional<AutoTimestepOptions> auto_timestep;
  // With auto_timestep: end a step at every sample time instead, so that
  // on_row is called with the simulation itself at the row's time (a
  // renderer draws the data, not the row).
  bool steps_end_at_rows = false;
  // This run's stop flag, or none: once *stop is true, Advance returns
  // (kInterrupted) before its next step. Set it from another thread or a
  // signal handler (std::atomic<bool> is lock-free there); it stops the runs
  // given it, and no other.
  const std::atomic<bool>* stop = nullptr;
};

// How a call of Advance ended.
struct AdvanceResult {
  enum class Status {
    kComplete,     // reached the duration (or the first episode's end)
    kDiverged,     // stopped at divergence (see divergence)
    kInterrupted,  // stopped by AdvanceOptions::stop
  };
  Status status = Status::kComplete;
  std::optional<Divergence> divergence;
  // Set when the total energy of an undriven scene grew beyond
  // kEnergyGrowthTolerance: how much, and when it was largest.
  std::optional<std::string> energy_growth;
  // With the auto timestep: the steps taken, and those at a contact's fine step.
  long steps = 0;
  long fine_steps = 0;
  // s: AutoTimestep::finest_step(), a fixed step as fine as the finest
  // step the rules asked for (infinite when no contact came near)
  double finest_step = 0;
};

// Steps sim from its current time until options.duration (or the first
// episode's end), calling on_row with Simulation::Sample() at every time
// k / sample_rate on the way, t = 0 included. Stops at divergence (the rows
// given so far are finite) and when options.stop is set. Checks the energy
// ledger of undriven scenes at every row and at the end.
AdvanceResult Advance(Simulation* sim, const AdvanceOptions& options,
                      const std::function<void(const std::vector<double>&)>& on_row);

}  // namespace contactlaws

#endif  // CONTACTLAWS_ADVANCE_H_
