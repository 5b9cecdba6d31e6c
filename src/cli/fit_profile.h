// Copyright contactlaws authors.
//
// fit --profile, --profile-points and --profile-budget: the winner's
// profile asked for (app/fit_job.h), parsed before anything runs
// (docs/identification.md).

#ifndef CONTACTLAWS_CLI_FIT_PROFILE_H_
#define CONTACTLAWS_CLI_FIT_PROFILE_H_

#include <optional>
#include <string>
#include <vector>

#include "app/fit_job.h"
#include "cli/identify.h"

namespace contactlaws::cli {

// nullopt without --profile. Refuses (one line, under its flag) a key not
// in --params, a key named twice, --profile-points outside [3, 200],
// --profile-budget outside [1, 1000000], either of them without --profile.
std::optional<app::ProfileRequest> ParseProfile(const FitArgs& args,
                                                const std::vector<FitParameter>& parameters,
                                                uint64_t seed);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_FIT_PROFILE_H_
