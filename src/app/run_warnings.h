// Copyright contactlaws authors.
//
// What a scene's tags and a finished run leave to warn about, options named
// by the front-end's reader (app/options.h).

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

// The warnings of a scene's tags, once each: their own (ContactModel::
// warnings, each naming its file and tag), and a scene without any.
std::vector<std::string> TagWarnings(const ContactModel& model);

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_RUN_WARNINGS_H_
