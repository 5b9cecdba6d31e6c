// Copyright contactlaws authors.
//
// Whether a scene's timestep resolves its contacts, said before a run, and the
// likely cause of a run that diverged.

#ifndef CONTACTLAWS_SIM_TIMESTEP_ADVICE_H_
#define CONTACTLAWS_SIM_TIMESTEP_ADVICE_H_

#include <optional>
#include <string>
#include <vector>

#include "memory/contact_memory.h"
#include "sim/estimate.h"
#include "sim/spelling.h"
#include "sim/start_contact.h"
#include "contactlaws/simulation.h"

namespace contactlaws {

// Each tag's estimated contact at the simulation's current state, and how
// many steps of the scene's timestep resolve it.
struct TimestepAdvice {
  int tag = -1;
  TagEstimate shortest;
  double steps = 0;     // per estimated contact duration (inf: not estimated)
  bool coarse = false;  // steps < kStepsPerContact
  // the friction of the shortest pair: its stick spring (or bristles, or
  // regularized curve), and whether the timestep is above its timestep()
  TangentialEstimate tangential;
  bool tangential_coarse = false;
  // the law's damping of the shortest pair at rest under its weight, and
  // whether the timestep is above its timestep()
  RestingEstimate resting;
  bool resting_coarse = false;
  // the tag's pair whose law's damping has the shortest lag where the run
  // starts (ShorterStartLag), and whether the timestep is above its
  // timestep()
  std::optional<StartContact> start;
  bool start_coarse = false;
};
// starts: StartContacts at the same state.
std::vector<TimestepAdvice> AdviseTimestep(Simulation* sim,
                                           const std::vector<StartContact>& starts);

// The pair of tag whose law's damping has the shortest lag where the run
// starts (starts: StartContacts), when that lag is shorter than rest_lag (s,
// the tag's at rest: RestingEstimate) beyond rounding: a start deeper than
// its load holds binds a fixed step to kFixedStepDamperLags of its lag.
// nullptr when none of tag's pairs starts in contact deeper than
// kTouchingGap, or its lag there is the one at rest.
const StartContact* ShorterStartLag(const ContactModel& cm, int tag,
                                    const std::vector<StartContact>& starts, double rest_lag);

// "contactlaw:TAG (g1, g2): timestep H s puts S steps in the estimated
// contact duration T s (>= 20 needed): use --timestep H' or smaller".
std::string CoarseTimestepWarning(const Simulation& sim, const TimestepAdvice& advice,
                                  const Spelling& spelling);

// "contactlaw:TAG (g1, g2): timestep H s puts S steps in the period P s of
// its stick spring (coulomb, k_t ...) (>= 20 needed): use --timestep H' or
// smaller".
std::string TangentialTimestepWarning(const Simulation& sim, const TimestepAdvice& advice,
                                      const Spelling& spelling);

// "contactlaw:TAG (g1, g2): timestep H s is longer than 2 lags of its law's
// damping at rest ...: use --timestep H' or smaller, or raise
// min_impact_velocity".
std::string RestingTimestepWarning(const Simulation& sim, const TimestepAdvice& advice,
                                   const Spelling& spelling);

// "contactlaw:TAG (g1, g2): timestep H s is longer than 2 lags of its law's
// damping where it starts (lag L s at the depth D m ...): use --timestep H'
// or smaller, or --settle".
std::string StartTimestepWarning(const Simulation& sim, const TimestepAdvice& advice,
                                 const Spelling& spelling);

// The options and commands each warning names are spelled by spelling (the
// caller's front-end).

// Every warning of advice (a fixed timestep's): CoarseTimestepWarning,
// TangentialTimestepWarning, RestingTimestepWarning and StartTimestepWarning
// of each tag that needs them.
std::vector<std::string> TimestepWarnings(const Simulation& sim,
                                          const std::vector<TimestepAdvice>& advice,
                                          const Spelling& spelling);

// "t = T s: contactlaw:TAG (g1, g2): depth D m, depth rate R m/s: WHAT;
// likely cause: ..." for a run stopped at divergence; advice from before the
// run names the timestep against the damper's lag where a pair starts, or
// against the estimated contact duration.
std::string DivergenceMessage(const Simulation& sim, const Divergence& divergence,
                              const std::vector<TimestepAdvice>& advice, const Spelling& spelling);

// "contactlaw:TAG (g1, g2)": a pair as messages name it.
std::string PairName(const Simulation& sim, int pair_index);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_TIMESTEP_ADVICE_H_
