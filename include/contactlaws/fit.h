// Copyright contactlaws authors.
//
// Fit: the parameters of a scene identified from measured trajectories, by
// minimising the mean score (score.h) of Replay over them with NLopt's
// optimisers. A parameter is
//   - a numeric key of the contactlaw tags (restitution, stiffness,
//     exponent, dissipation, mu_static, mu_kinetic, tangential_stiffness,
//     rolling_friction, ...), set on every tag as a number
//     (Overrides::values);
//   - BODY.mass_scale, BODY.inertia_scale: a body's mass or principal
//     inertia times the value;
//   - GEOM.offset: a geom moved along its own z axis (a plane's normal), m;
//   - mujoco.timeconst, .dampratio (solref), .dmin, .dmax, .width (solimp),
//     .friction (sliding): MuJoCo's own contact, on every geom, to fit the
//     untagged scene as a peer.
// Each is searched in [lo, hi], on a log scale when asked (lo > 0).
//
// The search: NLopt's CRS2 with local mutation (Kaelo & Ali 2006), a global
// controlled random search seeded by `seed`, over 70% of the budget, then
// BOBYQA (Powell 2009), a bounded local quadratic model, from the best point
// for the rest. Both work on the parameters scaled to [0, 1] and need no
// gradient (a rollout's score has none worth taking: a toss that lands on
// another face jumps). The evaluations are sequential and each one's mean is
// summed in trajectory order, so a seed gives the same result to the bit
// whatever the number of threads.

#ifndef CONTACTLAWS_FIT_H_
#define CONTACTLAWS_FIT_H_

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contactlaws/replay.h"
#include "contactlaws/statistics.h"

namespace contactlaws {

struct FitParameter {
  std::string key;  // as written: "stiffness", "cube.mass_scale", "board.offset"
  double lo = 0, hi = 0;
  bool log = false;
  // what it sets: a tag key (edit unused), or a model edit (edit.value unused)
  bool tag_key = true;
  ModelEdit edit;
  // The value at u in [0, 1].
  double At(double u) const;
  // The u of value, At's inverse (to rounding).
  double Unit(double value) const;
};

// "KEY=LO:HI[:log],KEY=..." checked against scene: a key that is neither a
// numeric tag key nor a model parameter, a body or geom the scene lacks,
// bounds that are not numbers, empty (lo >= hi), a log scale with lo <= 0,
// a range a model parameter cannot take, a key given twice. Throws Error
// "KEY=LO:HI: ..." (the command line adds "--params: "). The tag keys'
// ranges are checked by CheckFit.
std::vector<FitParameter> ParseFitParameters(std::string_view text, const mjModel* m);

// "KEY=VALUE,..." the start of a fit over parameters, one entry per
// parameter (nullopt: a key not given). Refuses (Error "KEY=VALUE: ...") an
// item not of that form, a key that is no parameter at all, a key
// not among parameters, a value that is not a finite number, a key given
// twice, and (CheckInitial) a value outside the key's bounds.
std::vector<std::optional<double>> ParseFitInitial(std::string_view text,
                                                   const std::vector<FitParameter>& parameters,
                                                   const mjModel* m);

// Refuses (Error naming the key, the value and the bounds) a start of
// another count than parameters' (an empty start is none) or a value
// outside its parameter's [lo, hi].
void CheckInitial(const std::vector<FitParameter>& parameters,
                  const std::vector<std::optional<double>>& initial);

// options with the parameters at values: a tag key's value set on every tag
// as a number (Overrides::values), a model parameter's as an edit.
ReplayOptions WithParameters(const ReplayOptions& options,
                             const std::vector<FitParameter>& parameters,
                             const std::vector<double>& values);

// Per parameter, whether a tag of the scene reads it under options' law and
// friction (model parameters always are).
std::vector<bool> ParametersRead(const Scene& scene, const ReplayOptions& options,
                                 const std::vector<FitParameter>& parameters);

// A law and a friction model (a tag's, with the overrides).
struct Combination {
  LawId law{};
  FrictionKind friction = FrictionKind::kCoulomb;
};

// The law and friction model of the scene's first contactlaw tag with the
// overrides; nullopt for a scene without one (MuJoCo's own contact).
std::optional<Combination> FirstCombination(const Scene& scene, const Overrides& overrides);

// "law/friction" of FirstCombination ("flores/coulomb"); "mujoco" for a
// scene without a contactlaw tag.
std::string CombinationName(const Scene& scene, const Overrides& overrides);

// Refuses (Error naming the key, and the file) a parameter no tag of the
// scene reads under options' law and friction, and bounds outside a tag
// key's range (the tags are read with each parameter at lo and at hi: "KEY=
// LO:HI: the bound HI is refused: FILE: contactlaw:TAG: KEY=HI must be ...").
void CheckFit(const Scene& scene, const ReplayOptions& options,
              const std::vector<FitParameter>& parameters);

struct FitOptions {
  ReplayOptions replay;  // the law, friction, start rule, metric's weights, threads
  Metric metric = Metric::kEq;
  std::vector<FitParameter> parameters;
  // The share of the trajectories, worst first, each evaluation's score
  // leaves out: 0 minimises the mean, 0.2 the mean of the best 80%
  // (TrimmedMean, statistics.h). In [0, 0.5).
  double trim = 0;
  int budget = 200;    // evaluations, each a replay of every trajectory
  uint64_t seed = 1;
  // Where the search starts: empty, every parameter at its range's middle;
  // else one entry per parameter, in its own units within [lo, hi] (nullopt:
  // that one at its middle). The first evaluation is this point.
  std::vector<std::optional<double>> initial;
  // After each evaluation: its number (from 1), its mean score, the best so far.
  std::function<void(int, double, double)> on_evaluation;
};

struct FitResult {
  std::vector<double> values;  // the best point, per parameter
  double score = 0;            // its (trimmed) mean score over the trajectories
  int evaluations = 0;
  bool interrupted = false;    // ReplayOptions::should_stop ended it
  double wall_seconds = 0;
};

// Minimises the (trimmed) mean score of replay's trajectories over the
// parameters, from options.initial (refused as CheckInitial does; a trim
// outside [0, 0.5) too).
FitResult Fit(const Replay& replay, const FitOptions& options);

// The mean of metric over replayed trajectories (0 when empty), summed in order.
double MeanScore(const std::vector<ReplayedTrajectory>& replayed, Metric metric);

// MeanScore at trim 0, else TrimmedMean (statistics.h) of metric.
double TrimmedMeanScore(const std::vector<ReplayedTrajectory>& replayed, Metric metric,
                        double trim);
// Profile: what the data determine about each parameter of a fitted point.
// Along one parameter, points across its range (evenly in u, so log-spaced
// on a log parameter) and the fitted value itself, the other parameters at
// their fitted values (or, with a budget, re-fitted from them at each
// point); each point replayed over every trajectory. The best point is the
// profile's lowest mean (trimmed as fit.trim says); every point's
// per-trajectory scores are compared with the best's, paired
// (ComparePairedTrimmed at fit.trim): a point whose interval contains 0
// is indistinguishable from the best. Pairing takes out what every point
// shares (a trajectory that every value scores badly): an unpaired test (a
// point's mean within the best point's interval) keeps it, and on noisy data
// calls alike points that every trajectory tells apart.
//
// The span: the contiguous indistinguishable points around the best, its
// ends at points (the true ends lie between them and the next points). A
// parameter is not determined by the data when its span covers at least a
// decade (a log parameter) or at least half its range (either scale).
struct ProfileOptions {
  int points = 9;  // across the range, ends included, >= 3
  // > 0: the other parameters re-fitted at each point (Fit, this many
  // evaluations, from the fitted values); 0: held at the fitted values
  int budget = 0;
  uint64_t seed = 1;  // the bootstrap's (and a re-fit's search)
  int resamples = kBootstrapResamples;
};

struct ProfilePoint {
  double value = 0;              // of the profiled parameter
  std::vector<double> values;    // every parameter's, re-fitted or held
  Summary score;                 // of the per-trajectory scores: mean with its interval
  double objective = 0;          // what the fit minimises: score's mean, or at fit.trim the trimmed mean
  PairedDifference versus_best;  // per-trajectory score less the best point's
  bool fitted = false;           // the fitted value itself
  bool Indistinguishable() const { return !versus_best.Distinguishable(); }
};

struct ParameterProfile {
  size_t parameter = 0;  // its index in FitOptions::parameters
  std::vector<ProfilePoint> points;  // in increasing value
  size_t best = 0;                   // the lowest mean (the first of equals)
  size_t span_first = 0, span_last = 0;  // points of the span, inclusive
  double span_lo() const { return points[span_first].value; }
  double span_hi() const { return points[span_last].value; }
  bool determined = true;
  bool interrupted = false;  // ReplayOptions::should_stop ended it: points are partial
};

// The points of a profile of parameter p through fitted, increasing:
// ProfileOptions' grid with fitted inserted where it falls (points + 1
// values), or in place of the grid's point it is within rounding of
// (points values). Throws Error for points < 3.
std::vector<double> ProfileValues(const FitParameter& p, double fitted, int points);

// Whether a span [lo, hi] of p leaves it not determined (see above).
bool SpanUndetermined(const FitParameter& p, double lo, double hi);

// The profiles of fit's parameters `which` (indices in fit.parameters)
// through fitted (one value per parameter), in which's order, with fit's
// replay options and metric. Throws Error for points < 3, fitted of
// another size than the parameters or outside their bounds (by more than a
// rounding: a value At(1) puts above hi is hi), an index out of range. A stop (ReplayOptions::should_stop) ends it: the profile being made
// is marked interrupted and no other is begun.
std::vector<ParameterProfile> Profile(const Replay& replay, const FitOptions& fit,
                                      const std::vector<double>& fitted,
                                      const std::vector<size_t>& which,
                                      const ProfileOptions& options);

}  // namespace contactlaws

#endif  // CONTACTLAWS_FIT_H_
