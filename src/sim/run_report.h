// Copyright contactlaws authors.
//
// What a finished run has to say about its contacts beyond the impact log.

#ifndef CONTACTLAWS_SIM_RUN_REPORT_H_
#define CONTACTLAWS_SIM_RUN_REPORT_H_

#include <string>
#include <vector>

#include "contactlaws/simulation.h"

namespace contactlaws {

// One line per tag with chained impacts (Episode::chained: touched slowly,
// then compressed far faster, as touching bodies are when a pulse comes
// through; not a contact there at the start that settles): its first such
// pair and how many more, how many impacts, the first one's touch speed
// and largest approach rate, and what the library did about it.
std::vector<std::string> ChainedContactWarnings(const Simulation& sim);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_RUN_REPORT_H_
