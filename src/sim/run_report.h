// Copyright contactlaws authors.
//
// What a finished run has to say about its contacts beyond the impact log.

#ifndef CONTACTLAWS_SIM_RUN_REPORT_H_
#define CONTACTLAWS_SIM_RUN_REPORT_H_

#include <cstdint>
#include <string>
#include <vector>

#include "sim/spelling.h"
#include "contactlaws/simulation.h"

namespace contactlaws {

// One line per tag with chained impacts (Episode::chained: touched slowly,
// then compressed far faster, as touching bodies are when a pulse comes
// through; not a contact there at the start that settles): its first such
// pair and how many more, how many impacts, the first one's touch speed
// and largest approach rate, and what the library did about it. A chained
// impact that touched slower than its law's floor of v0 and compressed no
// faster than twice the speed its bodies' weight sinks them to its depth
// (bodies placed touching, or come to rest, settling into their springs) is
// no push: such impacts make one line for the scene, pointing to settling
// (the option spelled by spelling, the caller's front-end).
std::vector<std::string> ChainedContactWarnings(const Simulation& sim, const Spelling& spelling);

// Per impact of sim.contacts().impacts(): whether it is bodies that touched
// slower than their law's floor of v0 sinking into their contact under their
// load (placed touching, or come to rest; the rule of the settling line
// above, chained or not): no impact, so no first impact's e_post (a contact
// placed touching that a later push lifts would read its lift-off speed
// against nothing).
std::vector<uint8_t> SettlingImpacts(const Simulation& sim);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_RUN_REPORT_H_
