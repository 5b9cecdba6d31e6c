// Copyright contactlaws authors.
//
// What a finished run leaves to warn about, its options named by the
// front-end's reader (app/options.h).

#ifndef CONTACTLAWS_APP_RUN_WARNINGS_H_
#define CONTACTLAWS_APP_RUN_WARNINGS_H_

#include <string>
#include <vector>

#include "app/options.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::app {

// The warnings a finished run leaves: energy growth, contacts chained
// through a body, a contact step's body turning too far, MuJoCo's own
// (with their counts).
std::vector<std::string> RunWarnings(const Simulation& sim, const AdvanceResult& result,
                                     const OptionReader& options);

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_RUN_WARNINGS_H_
