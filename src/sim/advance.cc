// Copyright contactlaws authors.

#include "contactlaws/simulation.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <fmt/format.h>

#include "sim/dense_rows.h"

namespace contactlaws {
namespace {

// AdvanceOptions::stop may be set from a signal handler
static_assert(std::atomic<bool>::is_always_lock_free);

// Watches the ledger's total of an undriven scene.
class EnergyWatch {
 public:
  // accuracy: the auto timestep's, when the steps are its
  EnergyWatch(const Simulation& sim, std::optional<double> accuracy)
      : enabled_(sim.Undriven()), accuracy_(accuracy) {}
  bool enabled() const { return enabled_; }
  // At a state after mj_forward.
  void Observe(const Simulation& sim) {
    if (!enabled_) return;
    const EnergyLedger e = sim.Energy();
    const double total = e.total();
    if (!started_) {
      started_ = true;
      initial_ = total;
      scale_ = std::abs(total);
    }
    scale_ = std::max(scale_, e.kinetic);
    const double growth = total - initial_;
    if (growth > worst_growth_) {
      worst_growth_ = growth;
      worst_time_ = sim.time();
    }
  }
  std::optional<std::string> Report() const {
    if (!enabled_ || !(worst_growth_ > kEnergyGrowthTolerance * scale_)) return std::nullopt;
    const std::string cause =
        accuracy_ ? fmt::format("likely an auto timestep's accuracy ({:.3g}) too coarse for the "
                                "contact: ask for a smaller one", *accuracy_)
                  : "likely a timestep too coarse for the contact";
    return fmt::format(
        "the total energy of this undriven scene grew by {:.4g} J ({:.3g}% of {:.4g} J, "
        "tolerance {}%) by t = {:.6g} s: the integration adds energy, {}",
        worst_growth_, 100 * worst_growth_ / scale_, scale_, 100 * kEnergyGrowthTolerance,
        worst_time_, cause);
  }

 private:
  bool enabled_;
  std::optional<double> accuracy_;
  bool started_ = false;
  double initial_ = 0;
  double scale_ = 0;
  double worst_growth_ = 0;
  double worst_time_ = 0;
};

}  // namespace

AdvanceResult Advance(Simulation* sim, const AdvanceOptions& options,
                      const std::function<void(const std::vector<double>&)>& on_row) {
  std::optional<AutoTimestep> stepper;
  if (options.auto_timestep) stepper.emplace(sim->contacts(), *options.auto_timestep);
  // times closer than this are the same grid time: half a fixed step, or a
  // nanosecond with auto steps (rows inside them are interpolated)
  const double tolerance = stepper ? 1e-9 : 0.5 * sim->model()->opt.timestep;
  const bool sampling = options.sample_rate > 0 && on_row;
  const double period = sampling ? 1.0 / options.sample_rate : 0.0;
  std::vector<double> row;
  EnergyWatch energy(*sim, options.auto_timestep
                               ? std::optional<double>(options.auto_timestep->accuracy)
                               : std::nullopt);
  AdvanceResult result;
  // auto steps do not end at sample times: the rows inside them are
  // interpolated (dense_rows.h)
  std::optional<DenseRows> dense;
  if (stepper && sampling && !options.steps_end_at_rows) dense.emplace(sim);

  // sample at the first step that reaches each grid time k * period (within
  // the tolerance, so that rounding of the time does not skip or repeat a row)
  long next = 0;
  auto sample_if_due = [&] {
    if (!sampling || sim->time() < next * period - tolerance) return;
    if (dense) {
      dense->End();
      energy.Observe(*sim);
      for (; next * period - tolerance <= sim->time(); ++next) {
        dense->Row(next * period, tolerance, &row);
        on_row(row);
      }
      return;
    }
    sim->Sample(&row);
    energy.Observe(*sim);
    on_row(row);
    while (next * period - tolerance <= sim->time()) ++next;
  };
  auto first_episode_over = [&] {
    for (const Episode& impact : sim->contacts().impacts()) {
      if (impact.tag == 0) return !impact.open;
    }
    return false;
  };

  if (!sampling && energy.enabled()) {
    mj_forward(sim->model(), sim->data());
    energy.Observe(*sim);
  }
  sample_if_due();
  while (sim->time() < options.duration - tolerance) {
    if (options.stop && options.stop->load(std::memory_order_relaxed)) {
      result.status = AdvanceResult::Status::kInterrupted;
      break;
    }
    if (stepper) {
      double until = options.duration - sim->time();
      if (sampling && !dense) until = std::min(until, next * period - sim->time());
      const double step = stepper->Next(sim->data(), until);
      if (dense && sim->time() + step >= next * period - 2 * tolerance) dense->Start();
      sim->Step(step);
    } else {
      sim->Step();
    }
    if (const std::optional<Divergence>& divergence = sim->contacts().divergence()) {
      result.status = AdvanceResult::Status::kDiverged;
      result.divergence = divergence;
      return result;  // the state is not to be sampled
    }
    sample_if_due();
    if (options.until_first_episode && first_episode_over()) break;
  }
  if (stepper) {
    result.steps = stepper->steps();
    result.fine_steps = stepper->fine_steps();
    result.finest_step = stepper->finest_step();
  }
  if (energy.enabled()) {
    mj_forward(sim->model(), sim->data());  // the ledger of the final state
    energy.Observe(*sim);
    result.energy_growth = energy.Report();
  }
  return result;
}

}  // namespace contactlaws
