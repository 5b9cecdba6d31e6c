// Copyright contactlaws authors.

#include "cli/fit_profile.h"

#include <algorithm>

#include <fmt/format.h>

#include "cli/options.h"
#include "scene/number.h"

namespace contactlaws::cli {

namespace {

constexpr long kMinPoints = 3;    // a best point and a neighbour each side
constexpr long kMaxPoints = 200;  // each point is a replay of every trajectory

// "restitution, mu": the keys of parameters.
std::string KeyList(const std::vector<FitParameter>& parameters) {
  std::string keys;
  for (const FitParameter& p : parameters) keys += (keys.empty() ? "" : ", ") + p.key;
  return keys;
}

}  // namespace

std::optional<app::ProfileRequest> ParseProfile(const FitArgs& args,
                                                const std::vector<FitParameter>& parameters,
                                                uint64_t seed) {
  if (!args.profile) {
    if (args.profile_points) {
      Refuse("--profile-points", *args.profile_points, "goes with --profile");
    }
    if (args.profile_budget) {
      Refuse("--profile-budget", *args.profile_budget, "goes with --profile");
    }
    return std::nullopt;
  }
  app::ProfileRequest request;
  request.options.seed = seed;
  const std::string& text = *args.profile;
  if (text == "all") {
    for (size_t i = 0; i < parameters.size(); ++i) request.keys.push_back(i);
  } else {
    size_t start = 0;
    while (start <= text.size()) {
      const size_t comma = text.find(',', start);
      const std::string key = text.substr(start, comma - start);
      const auto named = std::find_if(parameters.begin(), parameters.end(),
                                      [&](const FitParameter& p) { return p.key == key; });
      if (named == parameters.end()) {
        Refuse("--profile", text,
               fmt::format("has '{}', which is not a key of --params ({}) nor all", key,
                           KeyList(parameters)));
      }
      const size_t place = named - parameters.begin();
      if (std::find(request.keys.begin(), request.keys.end(), place) != request.keys.end()) {
        Refuse("--profile", text, fmt::format("names {} twice", key));
      }
      request.keys.push_back(place);
      start = comma == std::string::npos ? text.size() + 1 : comma + 1;
    }
  }
  if (args.profile_points) {
    const std::optional<long> points =
        ParseWholeNumber(*args.profile_points, kMinPoints, kMaxPoints);
    if (!points) {
      Refuse("--profile-points", *args.profile_points,
             fmt::format("must be a whole number in [{}, {}]", kMinPoints, kMaxPoints));
    }
    request.options.points = static_cast<int>(*points);
  }
  if (args.profile_budget) {
    const std::optional<long> budget = ParseWholeNumber(*args.profile_budget, 1, 1000000);
    if (!budget) {
      Refuse("--profile-budget", *args.profile_budget, "must be a whole number in [1, 1000000]");
    }
    request.options.budget = static_cast<int>(*budget);
  }
  return request;
}

}  // namespace contactlaws::cli
