// Copyright contactlaws authors.
//
// fit --profile: the winner's profile along the parameters asked
// (contactlaws/fit.h's Profile), parsed before anything runs, written to
// profile.csv and said in one line per parameter (docs/identification.md).

#ifndef CONTACTLAWS_CLI_FIT_PROFILE_H_
#define CONTACTLAWS_CLI_FIT_PROFILE_H_

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli/csv_file.h"
#include "cli/fit_ranking.h"
#include "cli/identify.h"

namespace contactlaws::cli {

// What --profile, --profile-points and --profile-budget ask.
struct ProfileRequest {
  std::vector<size_t> keys;  // places in --params, in --params' order for "all"
  ProfileOptions options;
};

// nullopt without --profile. Refuses (one line, under its flag) a key not
// in --params, a key named twice, --profile-points outside [3, 200],
// --profile-budget outside [1, 1000000], either of them without --profile.
std::optional<ProfileRequest> ParseProfile(const FitArgs& args,
                                           const std::vector<FitParameter>& parameters,
                                           uint64_t seed);

// The winner's profiles along the keys it reads (a key it does not read
// has none), over replay with the winner's options.
struct WinnerProfile {
  std::vector<ParameterProfile> profiles;
  std::vector<size_t> unread;  // places in --params the winner does not read
  bool interrupted = false;
};
WinnerProfile ProfileWinner(const Fitted& winner, const Replay& replay, const FitOptions& options,
                            const ProfileRequest& request, bool quiet);

// profile.csv: a row per point (with trim > 0, the trimmed mean beside the mean).
void WriteProfile(const Fitted& winner, const WinnerProfile& profile, double trim,
                  CsvFile* file);

// A line per profiled parameter: determined, or not, with its span.
void PrintProfile(const Fitted& winner, const WinnerProfile& profile,
                  const std::vector<FitParameter>& parameters, const ProfileRequest& request,
                  const MeasuredData& data, std::FILE* out);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_FIT_PROFILE_H_
