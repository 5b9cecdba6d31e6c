// Copyright contactlaws authors.
//
// The profile of a fitted point along each parameter (contactlaws/fit.h):
// the points, their scores, the paired comparison with the best, the span.

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"
#include "contactlaws/fit.h"

namespace contactlaws {

namespace {

// exp(log)'s rounding, in u or in decades: a span this close to a decade or
// to half the range reaches it; a grid point this close to the fitted value
// is it; a fitted value this far outside a bound is at it.
constexpr double kSpanRounding = 1e-9;

// The scores of one point, or false when a stop interrupted its replay.
bool Scores(const Replay& replay, const ReplayOptions& options, Metric metric,
            std::vector<double>* scores) {
  scores->clear();
  for (const ReplayedTrajectory& r : replay.Run(options)) {
    if (r.status == ReplayedTrajectory::Status::kInterrupted) return false;
    scores->push_back(r.score.Of(metric));
  }
  return true;
}

}  // namespace

std::vector<double> ProfileValues(const FitParameter& p, double fitted, int points) {
  if (points < 3) throw Error(fmt::format("a profile of {} points: needs 3 at least", points));
  std::vector<double> values;
  for (int k = 0; k < points; ++k) {
    // the ends exactly at the bounds, where At's exp(log) may round
    values.push_back(k == 0 ? p.lo : k == points - 1 ? p.hi : p.At(k / (points - 1.0)));
  }
  // a grid point within rounding of the fitted value is the fitted value:
  // beside it, it would differ from it by rounding alone, which a paired
  // comparison can tell apart
  const double u = p.Unit(fitted);
  for (double& v : values) {
    if (std::abs(p.Unit(v) - u) < kSpanRounding) {
      v = fitted;
      return values;
    }
  }
  values.insert(std::upper_bound(values.begin(), values.end(), fitted), fitted);
  return values;
}

bool SpanUndetermined(const FitParameter& p, double lo, double hi) {
  const bool half_range = p.Unit(hi) - p.Unit(lo) >= 0.5 - kSpanRounding;
  const bool decade = p.log && std::log10(hi / lo) >= 1 - kSpanRounding;
  return half_range || decade;
}

std::vector<ParameterProfile> Profile(const Replay& replay, const FitOptions& fit,
                                      const std::vector<double>& fitted,
                                      const std::vector<size_t>& which,
                                      const ProfileOptions& options) {
  const std::vector<FitParameter>& parameters = fit.parameters;
  if (fitted.size() != parameters.size()) {
    throw Error(fmt::format("a profile through {} values of {} parameters", fitted.size(),
                            parameters.size()));
  }
  // a fit's value at a bound is At(0) or At(1), which exp(log) may put a
  // rounding outside it: taken as the bound
  std::vector<double> through = fitted;
  for (size_t i = 0; i < parameters.size(); ++i) {
    const double u = parameters[i].Unit(through[i]);
    if (u < 0 && u > -kSpanRounding) through[i] = parameters[i].lo;
    if (u > 1 && u < 1 + kSpanRounding) through[i] = parameters[i].hi;
  }
  CheckInitial(parameters, std::vector<std::optional<double>>(through.begin(), through.end()));
  for (size_t i : which) {
    if (i >= parameters.size()) {
      throw Error(fmt::format("a profile of parameter {}: there are {}", i, parameters.size()));
    }
  }
  if (options.points < 3) {
    throw Error(fmt::format("a profile of {} points: needs 3 at least", options.points));
  }
  std::vector<ParameterProfile> profiles;
  std::vector<double> scores;
  std::vector<std::vector<double>> point_scores;
  std::vector<double> objective;
  for (size_t i : which) {
    const FitParameter& p = parameters[i];
    ParameterProfile profile;
    profile.parameter = i;
    point_scores.clear();
    objective.clear();  // per point, what the fit minimises: the (trimmed) mean
    for (double value : ProfileValues(p, through[i], options.points)) {
      ProfilePoint point;
      point.value = value;
      point.fitted = value == through[i];
      point.values = through;
      point.values[i] = value;
      if (options.budget > 0 && parameters.size() > 1) {
        // the others re-fitted from their fitted values, this one held at value
        FitOptions refit = fit;
        refit.replay = WithParameters(fit.replay, {p}, {value});
        refit.parameters.clear();
        refit.initial.clear();
        for (size_t k = 0; k < parameters.size(); ++k) {
          if (k == i) continue;
          refit.parameters.push_back(parameters[k]);
          refit.initial.push_back(through[k]);
        }
        refit.budget = options.budget;
        refit.seed = options.seed;
        refit.on_evaluation = nullptr;
        const FitResult result = Fit(replay, refit);
        if (result.interrupted || result.values.empty()) {
          profile.interrupted = true;
          break;
        }
        for (size_t k = 0, r = 0; k < parameters.size(); ++k) {
          if (k != i) point.values[k] = result.values[r++];
        }
      }
      if (!Scores(replay, WithParameters(fit.replay, parameters, point.values), fit.metric,
                  &scores)) {
        profile.interrupted = true;
        break;
      }
      point.score = Summarize(scores, options.seed, options.resamples);
      point.objective = fit.trim > 0 ? TrimmedMean(scores, fit.trim) : point.score.value.mean;
      objective.push_back(point.objective);
      profile.points.push_back(std::move(point));
      point_scores.push_back(scores);
    }
    if (!profile.interrupted) {
      // the best, compared with every point, and the span around it
      for (size_t k = 1; k < profile.points.size(); ++k) {
        if (objective[k] < objective[profile.best]) profile.best = k;
      }
      for (size_t k = 0; k < profile.points.size(); ++k) {
        profile.points[k].versus_best =
            ComparePairedTrimmed(point_scores[k], point_scores[profile.best], fit.trim,
                                 options.seed, options.resamples);
      }
      profile.span_first = profile.span_last = profile.best;
      while (profile.span_first > 0 && profile.points[profile.span_first - 1].Indistinguishable()) {
        --profile.span_first;
      }
      while (profile.span_last + 1 < profile.points.size() &&
             profile.points[profile.span_last + 1].Indistinguishable()) {
        ++profile.span_last;
      }
      profile.determined = !SpanUndetermined(p, profile.span_lo(), profile.span_hi());
    }
    const bool interrupted = profile.interrupted;
    profiles.push_back(std::move(profile));
    if (interrupted) break;
  }
  return profiles;
}

}  // namespace contactlaws
