// Copyright contactlaws authors.

#include "sim/timestep_advice.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "scene/tags.h"

namespace contactlaws {

std::string PairName(const Simulation& sim, int pair_index) {
  const ContactModel& cm = sim.contact_model();
  const GeomPair& pair = cm.pairs()[pair_index];
  return fmt::format("{}{} ({}, {})", kPairTagPrefix, cm.tags()[pair.tag].label,
                     ObjectName(sim.model(), mjOBJ_GEOM, pair.named[0]),
                     ObjectName(sim.model(), mjOBJ_GEOM, pair.named[1]));
}

namespace {

// A start's lag this much shorter than the one at rest binds the step: beyond
// DampingCoefficient's rounding (a block placed at its static depth has the
// same lag to 1e-15).
constexpr double kShorterLag = 1e-6;  // relative

}  // namespace

const StartContact* ShorterStartLag(const ContactModel& cm, int tag,
                                    const std::vector<StartContact>& starts, double rest_lag) {
  const StartContact* shortest = nullptr;
  for (const StartContact& s : starts) {
    if (cm.pairs()[s.pair].tag != tag) continue;
    if (!shortest || s.lag < shortest->lag) shortest = &s;
  }
  if (!shortest || !(shortest->lag < rest_lag * (1 - kShorterLag))) return nullptr;
  return shortest;
}

std::vector<TimestepAdvice> AdviseTimestep(Simulation* sim,
                                           const std::vector<StartContact>& starts) {
  mj_forward(sim->model(), sim->data());
  const double dt = sim->model()->opt.timestep;
  std::vector<TimestepAdvice> advice;
  for (int t = 0; t < static_cast<int>(sim->contact_model().tags().size()); ++t) {
    TimestepAdvice a;
    a.tag = t;
    a.shortest = EstimateTag(sim->contacts(), t);
    a.steps = a.shortest.StepsPerContact(dt);
    a.coarse = a.steps < kStepsPerContact;
    a.tangential = EstimateTangential(sim->contact_model(), a.shortest.pair, a.shortest.estimate);
    a.tangential_coarse = dt > a.tangential.timestep();
    a.resting = EstimateResting(sim->contact_model(), a.shortest.pair, a.shortest.estimate);
    a.resting_coarse = dt > a.resting.timestep();
    if (const StartContact* start =
            ShorterStartLag(sim->contact_model(), t, starts, a.resting.lag)) {
      a.start = *start;
      a.start_coarse = dt > start->timestep();
    }
    advice.push_back(a);
  }
  return advice;
}

namespace {

// "--timestep 6.66e-05", "timestep=6.66e-05"
std::string Timestep(const Spelling& spelling, double step) {
  return spelling.valued("timestep", fmt::format("{:.3g}", step));
}

}  // namespace

std::string CoarseTimestepWarning(const Simulation& sim, const TimestepAdvice& advice,
                                  const Spelling& spelling) {
  return fmt::format(
      "{}: timestep {} s puts {:.3g} steps in the estimated contact duration {:.4g} s "
      "(>= {} needed): use {} or smaller (see {})",
      PairName(sim, advice.shortest.pair), sim.model()->opt.timestep, advice.steps,
      advice.shortest.estimate.contact_duration, kStepsPerContact,
      Timestep(spelling, advice.shortest.estimate.timestep()), spelling.command("check"));
}

std::string TangentialTimestepWarning(const Simulation& sim, const TimestepAdvice& advice,
                                      const Spelling& spelling) {
  const TangentialEstimate& t = advice.tangential;
  const double dt = sim.model()->opt.timestep;
  const std::string needs =
      t.stiffness > 0 ? fmt::format("puts {:.3g} steps in the {} of its {} (>= {} needed)",
                                    2 * t.duration / dt, t.Span(), t.what, kStepsPerContact)
                      : fmt::format("is longer than the {} of its {} (a step each)", t.Span(),
                                    t.what);
  return fmt::format("{}: timestep {} s {}: use {} or smaller (see {})",
                     PairName(sim, advice.shortest.pair), dt, needs,
                     Timestep(spelling, t.timestep()), spelling.command("check"));
}

std::string RestingTimestepWarning(const Simulation& sim, const TimestepAdvice& advice,
                                   const Spelling& spelling) {
  const LawParams& law = sim.contact_model().pairs()[advice.shortest.pair].params;
  return fmt::format(
      "{}: timestep {} s is longer than 2 lags of its law's damping at rest (lag {:.3g} s: {} "
      "under the weight {:.4g} N at the v0 floor min_impact_velocity {} m/s): a resting contact "
      "would hang or chatter: use {} or smaller, or raise min_impact_velocity",
      PairName(sim, advice.shortest.pair), sim.model()->opt.timestep, advice.resting.lag,
      LawName(law.law), advice.resting.load, law.min_impact_velocity,
      Timestep(spelling, advice.resting.timestep()));
}

std::string StartTimestepWarning(const Simulation& sim, const TimestepAdvice& advice,
                                 const Spelling& spelling) {
  const StartContact& s = *advice.start;
  return fmt::format(
      "{}: timestep {} s is longer than {} lags of its law's damping where it starts (lag {:.3g} "
      "s at the depth {:.4g} m, its law's force {:.4g} N against the load {:.4g} N): use "
      "{} or smaller, or {}",
      PairName(sim, s.pair), sim.model()->opt.timestep, kFixedStepDamperLags, s.lag, s.depth,
      s.force, s.load, Timestep(spelling, s.timestep()), spelling.set("settle"));
}

std::vector<std::string> TimestepWarnings(const Simulation& sim,
                                          const std::vector<TimestepAdvice>& advice,
                                          const Spelling& spelling) {
  std::vector<std::string> warnings;
  // contacts integrated inside the step resolve the normal law's duration,
  // the tangential friction's period and their dampers in their sub-steps
  const bool inner = sim.contacts().contact_steps().enabled();
  for (const TimestepAdvice& a : advice) {
    if (a.coarse && !inner) warnings.push_back(CoarseTimestepWarning(sim, a, spelling));
    if (a.tangential_coarse && !inner) {
      warnings.push_back(TangentialTimestepWarning(sim, a, spelling));
    }
    if (a.resting_coarse && !inner) warnings.push_back(RestingTimestepWarning(sim, a, spelling));
    if (a.start_coarse && !inner) warnings.push_back(StartTimestepWarning(sim, a, spelling));
  }
  return warnings;
}

std::string DivergenceMessage(const Simulation& sim, const Divergence& divergence,
                              const std::vector<TimestepAdvice>& advice, const Spelling& spelling) {
  std::string where = divergence.pair >= 0
                          ? fmt::format("{}: depth {:.4g} m, depth rate {:.4g} m/s",
                                        PairName(sim, divergence.pair), divergence.depth,
                                        divergence.depth_rate)
                      : divergence.kind == Divergence::Kind::kMujocoReset
                          ? std::string("the contacts before MuJoCo's reset are lost")
                          : std::string("no tagged pair in contact");
  // the likely cause: the tag that diverged, else the first tag the
  // timestep does not resolve, else the first tag
  const int tag = divergence.pair >= 0 ? sim.contact_model().pairs()[divergence.pair].tag : -1;
  auto find = [&](auto&& which) -> const TimestepAdvice* {
    const auto found = std::find_if(advice.begin(), advice.end(), which);
    return found == advice.end() ? nullptr : &*found;
  };
  const TimestepAdvice* cause = find([&](const TimestepAdvice& a) { return a.tag == tag; });
  if (!cause) cause = find([](const TimestepAdvice& a) { return a.coarse || a.start_coarse; });
  if (!cause && !advice.empty()) cause = &advice.front();
  std::string likely;
  if (cause && cause->start_coarse) {
    const StartContact& s = *cause->start;
    likely = fmt::format(
        "likely cause: the timestep {} s is longer than {} lags of the law's damping where {} "
        "starts, {:.3g} s at the depth {:.4g} m ({}, or {})",
        sim.model()->opt.timestep, kFixedStepDamperLags, PairName(sim, s.pair), s.lag, s.depth,
        Timestep(spelling, s.timestep()), spelling.set("settle"));
  } else if (cause && std::isfinite(cause->steps)) {
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
          cause->coarse ? fmt::format(" (>= {} needed: {})", kStepsPerContact,
                                      Timestep(spelling, e.timestep()))
                        : std::string(" (enough for the estimate: check the stiffness, masses "
                                      "and speeds against the scene)"));
    }
  } else {
    likely = fmt::format(
        "likely cause: a timestep too coarse for the contact (the contact duration could not be "
        "estimated at the start: see {} {})",
        spelling.command("check"), spelling.name("impact_velocity"));
  }
  return fmt::format("t = {:.6g} s: {}: {}; {}", divergence.time, where, divergence.what,
                     likely);
}

}  // namespace contactlaws
