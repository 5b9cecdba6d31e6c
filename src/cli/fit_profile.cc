// Copyright contactlaws authors.

#include "cli/fit_profile.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "cli/impact_csv.h"
#include "cli/options.h"
#include "scene/number.h"
#include "scene/tag_keys.h"

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

// The unit of a parameter's values as printed after a number ("N/m^n",
// "m"), or "" for a ratio, a scale or a unit the key table describes in
// words rather than symbols.
std::string Unit(const FitParameter& p) {
  if (!p.tag_key) {
    switch (p.edit.kind) {
      case ModelEdit::Kind::kOffset: return "m";
      case ModelEdit::Kind::kMujocoTimeconst: return "s";
      case ModelEdit::Kind::kMujocoWidth: return "m";
      default: return "";
    }
  }
  const TagKey* key = FindTagKey(p.key);
  if (!key) return "";
  // "m, the torque cap over the normal force": the symbol before the comma
  std::string unit(key->unit.substr(0, key->unit.find(',')));
  if (unit.find(':') != std::string::npos || unit.find(" over ") != std::string::npos) return "";
  return unit;
}

}  // namespace

std::optional<ProfileRequest> ParseProfile(const FitArgs& args,
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
  ProfileRequest request;
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

WinnerProfile ProfileWinner(const Fitted& winner, const Replay& replay, const FitOptions& options,
                            const ProfileRequest& request, bool quiet) {
  WinnerProfile out;
  for (size_t place : request.keys) {
    const auto at = std::find(winner.place.begin(), winner.place.end(), place);
    if (at == winner.place.end()) {
      out.unread.push_back(place);
      continue;
    }
    const size_t k = at - winner.place.begin();
    if (!quiet) {
      fmt::print(stderr, "profile {}: {}: {} points{}\n", winner.label, winner.parameters[k].key,
                 request.options.points,
                 request.options.budget > 0
                     ? fmt::format(", the others re-fitted over {} evaluations each",
                                   request.options.budget)
                     : "");
    }
    std::vector<ParameterProfile> one =
        Profile(replay, options, winner.fit.values, {k}, request.options);
    out.interrupted = one.empty() || one.front().interrupted;
    if (out.interrupted) break;
    out.profiles.push_back(std::move(one.front()));
  }
  return out;
}

void WriteProfile(const Fitted& winner, const WinnerProfile& profile, double trim,
                  CsvFile* file) {
  std::vector<std::string> header = {"key", "scale", "value", "fitted", "mean", "mean_lo", "mean_hi"};
  if (trim > 0) header.emplace_back("trimmed_mean");
  for (const char* c : {"versus_best", "versus_best_lo", "versus_best_hi", "indistinguishable",
                        "span_lo", "span_hi", "determined"}) {
    header.emplace_back(c);
  }
  file->Header(header);
  for (const ParameterProfile& profile : profile.profiles) {
    const FitParameter& p = winner.parameters[profile.parameter];
    for (size_t k = 0; k < profile.points.size(); ++k) {
      const ProfilePoint& point = profile.points[k];
      const PairedDifference& d = point.versus_best;
      std::vector<std::string> row = {p.key, p.log ? "log" : "linear", Field(point.value),
                                      point.fitted ? "yes" : "no", Field(point.score.value.mean),
                                      Field(point.score.mean.lo), Field(point.score.mean.hi)};
      if (trim > 0) row.push_back(Field(point.objective));
      for (std::string field :
           {Field(d.mean), Field(d.interval.lo), Field(d.interval.hi),
            std::string(k == profile.best ? "best" : point.Indistinguishable() ? "yes" : "no"),
            Field(profile.span_lo()), Field(profile.span_hi()),
            std::string(profile.determined ? "yes" : "no")}) {
        row.push_back(std::move(field));
      }
      file->Fields(row);
    }
  }
}

void PrintProfile(const Fitted& winner, const WinnerProfile& profile,
                  const std::vector<FitParameter>& parameters, const ProfileRequest& request,
                  const MeasuredData& data, std::FILE* out) {
  fmt::print(out, "profile of {} on {} ({} points per parameter and the fitted value, {}; a point "
             "scores the same as the best when the paired 95% bootstrap interval of its "
             "per-trajectory difference contains 0):\n",
             winner.label, data.source, request.options.points,
             request.options.budget > 0
                 ? fmt::format("the others re-fitted over {} evaluations at each",
                               request.options.budget)
                 : "the others held at their fitted values");
  for (const ParameterProfile& pr : profile.profiles) {
    const FitParameter& p = winner.parameters[pr.parameter];
    const std::string unit = Unit(p);
    const std::string span = fmt::format("[{:.3g}, {:.3g}]{}", pr.span_lo(), pr.span_hi(),
                                         unit.empty() ? "" : " " + unit);
    const double best = pr.points[pr.best].value;
    const std::string at_bound = best == p.lo || best == p.hi
                                     ? fmt::format("; the best is at the range's bound {:.3g}: "
                                                   "a wider range may score better",
                                                   best)
                                     : "";
    if (pr.determined) {
      fmt::print(out, "  {}: determined: {:.3g} {} (the values that score the same as the best, "
                 "{:.3g}){}\n",
                 p.key, winner.fit.values[pr.parameter], span, best, at_bound);
    } else {
      // how wide: decades on a log scale, the share of the range on either
      const std::string width =
          p.log ? fmt::format("{:.1f} decades", std::log10(pr.span_hi() / pr.span_lo()))
                : fmt::format("{:.0f}% of the range",
                              100 * (pr.span_hi() - pr.span_lo()) / (p.hi - p.lo));
      fmt::print(out, "  {}: not determined by the data: any value in {} scores the same as the "
                 "best ({:.3g}): {}{}\n",
                 p.key, span, best, width, at_bound);
    }
  }
  for (size_t place : profile.unread) {
    fmt::print(out, "  {}: no profile: {} does not read it\n", parameters[place].key,
               winner.label);
  }
}

}  // namespace contactlaws::cli
