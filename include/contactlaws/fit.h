// Copyright contactlaws authors.
//
// Fit: the parameters of a scene identified from measured trajectories, by
// minimising the mean score (replay.h) of Replay over them with NLopt's
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

#include <mujoco/mujoco.h>

#include "contactlaws/replay.h"

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
  // (TrimmedMean, replay.h). In [0, 0.5).
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

// MeanScore at trim 0, else TrimmedMean (replay.h) of metric.
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

// ---------------------------------------------------------------------------
// Where measured bodies come to rest, and how far a replay's last state is
// from the measured one (docs/identification.md, "Resting poses"):
//
//   at rest      a trajectory whose body moves slower than RestRule::speed
//                between each of its last RestRule::samples samples;
//   plane height a body at rest on a plane: its resting height (the mean
//                over the samples found at rest) less its support distance
//                (the depth of its lowest point below its origin on the
//                face it rests on: a cube's half side), one estimate per
//                trajectory at rest;
//   end gaps     the last sample's simulated position less the measured
//                (height and horizontal distance), the rotation between the
//                two orientations, and the tilt: the angle between the
//                vertical seen from the simulated body and from the measured
//                one, which a turn about the vertical leaves at 0. A tilt
//                above 45 degrees puts another side of a cube up: "another
//                face".

// The cube tosses' tracking (148 Hz) moves a resting cube by ~0.008 m/s
// from sample to sample (the median over the last 5 intervals of the
// training tosses); 0.02 m/s is 2.5 times that, 0.14 mm per sample.
struct RestRule {
  double speed = 0.02;  // m/s
  int samples = 5;      // the last intervals checked
};

// A body of the data: its name and its x and qw columns (qw -1 when its
// orientation is not measured).
struct MeasuredBodyColumns {
  std::string name;
  int x = -1, qw = -1;
};
// Every NAME with NAME.x, NAME.y and NAME.z columns, in the data's order.
std::vector<MeasuredBodyColumns> MeasuredBodies(const MeasuredData& data);

// Whether body ends trajectory t at rest under rule (a trajectory shorter
// than rule.samples + 1 samples does not).
bool EndsAtRest(const MeasuredData& data, const MeasuredTrajectory& t,
                const MeasuredBodyColumns& body, const RestRule& rule);

// How far body's lowest point lies below its origin along the world's z,
// at orientation q (w, x, y, z): the largest support distance of its
// colliding geoms (box, sphere, capsule, cylinder, ellipsoid). resting: each
// geom on its face, end or side nearest to facing down (the world's -z
// snapped to the geom's nearest axis), as a body at rest lies; a tracked
// orientation's error of a degree, which the support function's corner
// turns into a bias (+0.7 mm on the tosses' resting cubes), then drops out.
// Throws Error naming the body for another geom type or a body without
// colliding geoms.
double SupportDistance(const mjModel* m, int body, const double q[4], bool resting = false);

// At least this many trajectories at rest for a plane's estimate: fewer
// leave its bootstrap interval resampling one or two values.
inline constexpr int kMinimumAtRest = 5;

struct PlaneEstimate {
  int trajectories = 0;  // of every measured body
  int at_rest = 0;
  Summary height;  // the plane's height, m: median and its interval, per trajectory at rest
  Distribution support;  // the support distances, m
};
// The height of the plane the data's bodies rest on (bodies of m named as
// in the data; orientations the model's own when not measured). Throws
// Error, in one line naming the data, the rule and how many came to rest,
// when fewer than kMinimumAtRest did.
PlaneEstimate EstimatePlaneHeight(const mjModel* m, const MeasuredData& data,
                                  const RestRule& rule, uint64_t seed);

// One body's gaps at trajectory i's last sample.
struct EndGap {
  bool at_rest = false;       // the measured trajectory ends at rest
  double measured_z = 0;      // m
  double simulated_z = 0;     // m
  double horizontal = 0;      // m
  double angle = 0;           // rad, the whole rotation (0 unmeasured)
  double tilt = 0;            // rad, the vertical's (0 unmeasured)
};
// Per trajectory, per body of MeasuredBodies (its order): replayed[i].last
// against data's last sample.
std::vector<std::vector<EndGap>> EndGaps(const MeasuredData& data,
                                         const std::vector<ReplayedTrajectory>& replayed,
                                         const RestRule& rule);

// A cube's neighbouring faces are 90 degrees apart: half that.
inline constexpr double kAnotherFaceTilt = 0.7853981633974483;  // pi / 4, rad

// ---------------------------------------------------------------------------
// Per-trajectory scores in units a person reads, beside the fit's metric
// (docs/identification.md, "Scores a person reads"), and the resting gaps
// summarised per body. Each array is one value per replayed trajectory, in
// the data's order: Summarize (replay.h) summarises them.

struct ScoreArray {
  // "" for the metric itself (ranking.csv's train_mean ...), else the
  // column's stem: "e_q", "position_mm", "angle_deg", "final_angle_deg",
  // "another_face"
  std::string name;
  std::vector<double> values;
  // a share (values 0 or 1): its mean alone is read, with its interval
  bool share = false;
};

// metric's values; e_q's when metric is another; the position and angle
// RMS in mm and degrees; the last sample's rotation (degrees, the largest
// of the bodies'); another face: 1 where a body's last tilt (above)
// exceeds kAnotherFaceTilt.
std::vector<ScoreArray> ReadableScores(const MeasuredData& data,
                                       const std::vector<ReplayedTrajectory>& replayed,
                                       Metric metric);

// One body's resting gaps over the trajectories that end at rest.
struct RestingGaps {
  std::string body;
  int trajectories = 0, at_rest = 0;
  Summary measured_z, simulated_z, gap_z;  // m; gap: simulated - measured
  double gap_z_p25 = 0, gap_z_p75 = 0;     // m, its spread
  Distribution horizontal, angle;          // m, rad
};
std::vector<RestingGaps> SummarizeRestingGaps(const MeasuredData& data,
                                              const std::vector<ReplayedTrajectory>& replayed,
                                              const RestRule& rule, uint64_t seed);

}  // namespace contactlaws

#endif  // CONTACTLAWS_FIT_H_
