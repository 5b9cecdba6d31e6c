// Copyright contactlaws authors.
//
// The tagged pairs in contact where a run starts, before it: the law's force
// and damping at their points' depths, and the load that presses each. A
// pair placed deeper than its load holds it starts with its spring
// compressed beyond where any body placed touching sinks: released, it
// throws the bodies apart, and its damper (c = a F / v0 for the hysteresis
// family) is as many times stiffer than at rest as its force is larger than
// the load, its lag as many times shorter.

#ifndef CONTACTLAWS_SIM_START_CONTACT_H_
#define CONTACTLAWS_SIM_START_CONTACT_H_

#include <limits>
#include <string>
#include <vector>

#include "sim/spelling.h"
#include "contactlaws/simulation.h"
#include "sim/estimate.h"

namespace contactlaws {

struct StartContact {
  int pair = -1;     // ContactModel::pairs() index
  int points = 0;    // its contact points
  double depth = 0;  // m, its deepest point's
  double force = 0;  // N, the law's normal force over its points
  // N, what presses the pair together: on each side that can move, the
  // pair's force on it less its subtree's mass times acceleration along the
  // normal (Newton: gravity, joints, other contacts, all in qacc); the
  // smaller of the two sides
  double load = 0;
  // s, DamperLag of its points' law damping on the pair's effective mass
  double lag = std::numeric_limits<double>::infinity();
  double timestep() const { return kFixedStepDamperLags * lag; }
  // force > DeepStartFactor x load
  bool deep = false;
};

// The ratio of a start's force to its load beyond which it is deep: n + 1
// (2 for kelvin-voigt). A body placed touching (d = 0) and released under a
// load W sinks, undamped, to the depth where W d = K d^(n+1) / (n+1), where
// the force is (n + 1) W: a start beyond that holds more elastic energy than
// any placement at touch releases.
double DeepStartFactor(const LawParams& law);

// Every tagged pair in contact at sim's current state deeper than
// kTouchingGap (closer is placed touching: settle.h), in pair order. Calls
// mj_forward.
std::vector<StartContact> StartContacts(Simulation* sim);

// One line per tag with a deep start: its pair of the largest force per
// load, its depth, force and load, and how many more pairs of the tag start
// deep; what follows, and settling (the option and command spelled by
// spelling, the caller's front-end).
std::vector<std::string> DeepStartWarnings(const Simulation& sim,
                                           const std::vector<StartContact>& starts,
                                           const Spelling& spelling);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_START_CONTACT_H_
