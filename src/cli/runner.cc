// Copyright contactlaws authors.

#include "cli/runner.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <set>

#include <fmt/format.h>

#include "contactlaws/tags.h"

namespace contactlaws::cli {
namespace {

// Set by RequestStop (a signal handler among others): lock-free, so
// async-signal-safe, and read once per step by every running Advance.
std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

std::string PairName(const Simulation& sim, int pair_index) {
  const ContactModel& cm = sim.contact_model();
  const GeomPair& pair = cm.pairs()[pair_index];
  return fmt::format("{}{} ({}, {})", kPairTagPrefix, cm.tags()[pair.tag].label,
                     ObjectName(sim.model(), mjOBJ_GEOM, pair.named[0]),
                     ObjectName(sim.model(), mjOBJ_GEOM, pair.named[1]));
}

// Watches the ledger's total of an undriven scene.
class EnergyWatch {
 public:
  explicit EnergyWatch(const Simulation& sim) : enabled_(sim.Undriven()) {}
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
    return fmt::format(
        "the total energy of this undriven scene grew by {:.4g} J ({:.3g}% of {:.4g} J, "
        "tolerance {}%) by t = {:.6g} s: the integration adds energy, likely a timestep too "
        "coarse for the contact",
        worst_growth_, 100 * worst_growth_ / scale_, scale_, 100 * kEnergyGrowthTolerance,
        worst_time_);
  }

 private:
  bool enabled_;
  bool started_ = false;
  double initial_ = 0;
  double scale_ = 0;
  double worst_growth_ = 0;
  double worst_time_ = 0;
};

struct MujocoMessages {
  std::mutex mutex;
  std::map<std::string, int> received;  // text -> times
  std::set<std::string> reported;
};

MujocoMessages& Messages() {
  static MujocoMessages* messages = new MujocoMessages;  // used until exit
  return *messages;
}

}  // namespace

void RecordMujocoWarning(const char* text) {
  MujocoMessages& m = Messages();
  std::lock_guard lock(m.mutex);
  ++m.received[text ? text : ""];
}

void NoteReportedMujocoWarning(const std::string& text) {
  MujocoMessages& m = Messages();
  std::lock_guard lock(m.mutex);
  m.reported.insert(text);
}

std::vector<MujocoWarning> UnreportedMujocoWarnings() {
  MujocoMessages& m = Messages();
  std::lock_guard lock(m.mutex);
  std::vector<MujocoWarning> unreported;
  for (const auto& entry : m.received) {
    const std::string& text = entry.first;
    // MuJoCo sends a run's warning text with " Time = ..." appended
    const bool reported = std::any_of(m.reported.begin(), m.reported.end(),
                                      [&](const std::string& r) { return text.rfind(r, 0) == 0; });
    if (!reported) unreported.push_back({text, entry.second});
  }
  return unreported;
}

void RequestStop() { stop_requested.store(true, std::memory_order_relaxed); }

bool StopRequested() { return stop_requested.load(std::memory_order_relaxed); }

Scene::Scene(std::string path) : path_(std::move(path)), model_(LoadModelFile(path_)) {}

Scene::Scene(std::string name, UniqueModel model)
    : path_(std::move(name)), model_(std::move(model)) {}

std::unique_ptr<Simulation> Scene::Make(const SimulationOptions& options) const {
  UniqueModel copy(mj_copyModel(nullptr, model_.get()));
  if (!copy) throw Error(fmt::format("{}: MuJoCo could not copy the model", path_));
  return std::make_unique<Simulation>(std::move(copy), path_, options);
}

double ReportedRestitution(LawKind law, double restitution) {
  return law == LawKind::kHertz ? 1.0 : restitution;
}

AdvanceResult Advance(Simulation* sim, const AdvanceOptions& options,
                      const std::function<void(const std::vector<double>&)>& on_row) {
  std::optional<AutoTimestep> stepper;
  if (options.auto_timestep) stepper.emplace(sim->contacts(), *options.auto_timestep);
  // times closer than this are the same grid time: half a fixed step, or a
  // nanosecond with auto steps (which land on the grid)
  const double tolerance = stepper ? 1e-9 : 0.5 * sim->model()->opt.timestep;
  const bool sampling = options.sample_rate > 0 && on_row;
  const double period = sampling ? 1.0 / options.sample_rate : 0.0;
  std::vector<double> row;
  EnergyWatch energy(*sim);
  AdvanceResult result;

  // sample at the first step that reaches each grid time k * period (within
  // the tolerance, so that rounding of the time does not skip or repeat a row)
  long next = 0;
  auto sample_if_due = [&] {
    if (!sampling || sim->time() < next * period - tolerance) return;
    sim->Sample(&row);
    energy.Observe(*sim);
    on_row(row);
    while (next * period - tolerance <= sim->time()) ++next;
  };
  auto first_episode_over = [&] {
    for (const Impact& impact : sim->contacts().impacts()) {
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
    if (StopRequested()) {
      result.status = AdvanceResult::Status::kInterrupted;
      break;
    }
    if (stepper) {
      double until = options.duration - sim->time();
      if (sampling) until = std::min(until, next * period - sim->time());
      sim->Step(stepper->Next(until));
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
  }
  if (energy.enabled()) {
    mj_forward(sim->model(), sim->data());  // the ledger of the final state
    energy.Observe(*sim);
    result.energy_growth = energy.Report();
  }
  return result;
}

std::vector<TimestepAdvice> AdviseTimestep(Simulation* sim) {
  mj_forward(sim->model(), sim->data());
  const double dt = sim->model()->opt.timestep;
  std::vector<TimestepAdvice> advice;
  for (int t = 0; t < static_cast<int>(sim->contact_model().tags().size()); ++t) {
    TimestepAdvice a;
    a.tag = t;
    a.shortest = EstimateTag(sim->contacts(), t);
    a.steps = a.shortest.StepsPerContact(dt);
    a.coarse = a.steps < kStepsPerContact;
    advice.push_back(a);
  }
  return advice;
}

std::string CoarseTimestepWarning(const Simulation& sim, const TimestepAdvice& advice) {
  return fmt::format(
      "{}: timestep {} s puts {:.3g} steps in the estimated contact duration {:.4g} s "
      "(>= {} needed): use --timestep {:.3g} or smaller (see contactlaws check)",
      PairName(sim, advice.shortest.pair), sim.model()->opt.timestep, advice.steps,
      advice.shortest.estimate.contact_duration, kStepsPerContact,
      advice.shortest.estimate.timestep());
}

std::string DivergenceMessage(const Simulation& sim, const Divergence& divergence,
                              const std::vector<TimestepAdvice>& advice) {
  std::string where = divergence.pair >= 0
                          ? fmt::format("{}: depth {:.4g} m, depth rate {:.4g} m/s",
                                        PairName(sim, divergence.pair), divergence.depth,
                                        divergence.depth_rate)
                          : std::string("no tagged pair in contact");
  // the likely cause: the tag that diverged, else the first tag the
  // timestep does not resolve, else the first tag
  const int tag = divergence.pair >= 0 ? sim.contact_model().pairs()[divergence.pair].tag : -1;
  auto find = [&](auto&& which) -> const TimestepAdvice* {
    const auto found = std::find_if(advice.begin(), advice.end(), which);
    return found == advice.end() ? nullptr : &*found;
  };
  const TimestepAdvice* cause = find([&](const TimestepAdvice& a) { return a.tag == tag; });
  if (!cause) cause = find([](const TimestepAdvice& a) { return a.coarse; });
  if (!cause && !advice.empty()) cause = &advice.front();
  std::string likely;
  if (cause && std::isfinite(cause->steps)) {
    const ContactEstimate& e = cause->shortest.estimate;
    const double limit = sim.contact_model().pairs()[cause->shortest.pair].depth_limit;
    if (e.max_depth > limit) {
      likely = fmt::format(
          "likely cause: a contact too soft for the impact: the estimated elastic depth of {} "
          "at {:.4g} m/s is {:.4g} m, beyond {:.4g} m (raise the stiffness)",
          PairName(sim, cause->shortest.pair), e.impact_velocity, e.max_depth, limit);
    } else {
      likely = fmt::format(
          "likely cause: the timestep {} s puts {:.3g} steps in the estimated contact duration "
          "{:.4g} s of {}{}",
          sim.model()->opt.timestep, cause->steps, e.contact_duration,
          PairName(sim, cause->shortest.pair),
          cause->coarse ? fmt::format(" (>= {} needed: --timestep {:.3g})", kStepsPerContact,
                                      e.timestep())
                        : std::string(" (enough for the estimate: check the stiffness, masses "
                                      "and speeds against the scene)"));
    }
  } else {
    likely = "likely cause: a timestep too coarse for the contact (the contact duration could "
             "not be estimated at the start: see contactlaws check --impact-velocity)";
  }
  return fmt::format("t = {:.6g} s: {}: {}; {}", divergence.time, where, divergence.what,
                     likely);
}

std::vector<std::string> ImpactColumns() {
  return {"law", "restitution", "pair", "geom1", "geom2", "index", "time_contact",
          "time_separation", "impact_velocity", "separation_velocity", "restitution_post",
          "max_depth", "max_force"};
}

std::string Field(double value) { return fmt::format("{}", value); }

std::string Field(const std::optional<double>& value) { return value ? Field(*value) : ""; }

std::vector<std::string> ImpactFields(const Simulation& sim, const Impact& impact) {
  const ContactModel& cm = sim.contact_model();
  const PairTag& tag = cm.tags()[impact.tag];
  const GeomPair& pair = cm.pairs()[impact.pair];
  const bool closed = !impact.open;
  auto if_closed = [closed](double v) { return closed ? Field(v) : std::string(); };
  return {std::string(LawName(tag.law)),
          Field(ReportedRestitution(tag.law, pair.params.restitution)),
          tag.label,
          ObjectName(sim.model(), mjOBJ_GEOM, pair.named[0]),
          ObjectName(sim.model(), mjOBJ_GEOM, pair.named[1]),
          Field(impact.index),
          Field(impact.time_contact),
          if_closed(impact.time_separation),
          Field(impact.impact_velocity),
          if_closed(impact.separation_velocity),
          if_closed(impact.restitution_post()),
          Field(impact.max_depth),
          Field(impact.max_force)};
}

}  // namespace contactlaws::cli
