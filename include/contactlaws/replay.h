// Copyright contactlaws authors.
//
// Replay: a tagged scene simulated from the start of each measured
// trajectory (MeasuredData) to its last sample, and scored against it
// (the scores, below). One compiled scene, one Simulation per thread reused across
// trajectories (Reset and the start state per trajectory), trajectories
// spread over threads; the scores do not depend on the number of threads.
//
// What is measured is set at the start: a measured body's free joint takes
// its position, orientation and velocities, a measured hinge or slide its q
// and v; everything else starts as the scene says (keyframe 0 or qpos0).
// Velocities not measured come from the first two samples (finite
// differences: the linear rate, and the rotation between them as a constant
// angular velocity).

#ifndef CONTACTLAWS_REPLAY_H_
#define CONTACTLAWS_REPLAY_H_

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contactlaws/auto_timestep.h"
#include "contactlaws/simulation.h"

namespace contactlaws {

// ---------------------------------------------------------------------------
// Measured trajectories (docs/identification.md): a long CSV, one row per
// sample,
//
//   trajectory,time,<body>.x,.y,.z,.qw,.qx,.qy,.qz[,.vx,.vy,.vz,.wx,.wy,.wz],
//              <joint>.q[,.v],...
//
// with the run CSV's own column names and units: positions in m, the body's
// orientation as the unit quaternion (w, x, y, z) from its frame to the
// world's, linear velocity in m/s and angular velocity in rad/s, both in the
// world frame; a hinge's q in rad, a slide's in m. The rows of one
// trajectory are consecutive, its times strictly increasing.

// One trial: its samples, row by row.
struct MeasuredTrajectory {
  std::string name;          // the trajectory column's value
  int first_row = 0;         // the file's line of its first sample (header: 1)
  std::vector<double> time;  // s, strictly increasing
  // sample k's value of column c (MeasuredData::columns) at k * columns + c
  std::vector<double> values;
  int samples() const { return static_cast<int>(time.size()); }
};

struct MeasuredData {
  std::string source;                // the file, for messages
  std::vector<std::string> columns;  // the columns after trajectory,time
  std::vector<MeasuredTrajectory> trajectories;
  // The index of a column in columns, -1 when absent.
  int Column(std::string_view name) const;
};

// The columns a trajectory CSV may give for a body, in the order they are
// written, and a joint's.
inline constexpr const char* kBodyQuantities[] = {"x",  "y",  "z",  "qw", "qx", "qy", "qz",
                                                  "vx", "vy", "vz", "wx", "wy", "wz"};
inline constexpr const char* kJointQuantities[] = {"q", "v"};

// A quaternion column group whose norm is off unity by more than this is
// refused: the tracking writes ~7 digits (1e-6), a quaternion that far off
// is not a rotation.
inline constexpr double kQuaternionNormTolerance = 1e-3;

// Reads and checks a trajectory file. Throws Error naming the file, the row
// (its line), the column and the value: a header without trajectory,time
// first, a repeated or malformed column, a row of another width, a value
// that is not a finite number, a time not strictly increasing within a
// trajectory, a trajectory whose rows are not consecutive or that has fewer
// than 2 samples, a quaternion far from unit norm, an empty file.
MeasuredData ReadMeasuredData(const std::string& path);

// The same from text in memory; source names it in messages.
MeasuredData ParseMeasuredData(std::string_view text, const std::string& source);

// The same from a table's columns (Python's DataFrame): per sample its
// trajectory's name and its time (s), and the measured columns' names with
// their values (values[c][k]: column c at sample k), checked as a file is;
// a sample is named in messages "SOURCE row K" (K from 0). Also throws
// Error for columns of other lengths than the samples'.
MeasuredData MeasuredFromColumns(const std::vector<std::string>& trajectory,
                                 const std::vector<double>& time,
                                 const std::vector<std::string>& columns,
                                 const std::vector<std::vector<double>>& values,
                                 const std::string& source);

// ---------------------------------------------------------------------------
// How far a simulated trajectory is from a measured one: every score of
// replay and fit is computed here, one way. Per sample k and measured body
// b (position p, orientation q) or joint j (coordinate q_j):
//
//   dp2(k, b)    = |p_sim - p_meas|^2                         m^2
//   theta(k, b)  = the angle of the rotation q_sim^-1 q_meas   rad, in [0, pi]
//   dq2(k, j)    = (q_sim - q_meas)^2                          rad^2 or m^2
//
// and over the samples (means over every sample and every body or joint
// that has the quantity):
//
//   e_q          = mean of dp2 / L_b + theta^2   (Acosta, Yang & Posa 2022;
//                  L_b a length of body b, the cube's half side there), 1
//   position_rms = sqrt(mean dp2), m
//   angle_rms    = sqrt(mean theta^2), rad
//   joint_rms    = sqrt(mean dq2), rad or m
//   weighted     = P position_rms + A angle_rms + J joint_rms (ScoreWeights)
//
// e_q's first term has units of a length (m^2 / m): the published
// definition, kept as it is so that its numbers compare.

enum class Metric { kEq, kPositionRms, kAngleRms, kWeighted };

// "e_q", "position_rms", "angle_rms", "weighted"; nullopt for anything else.
std::optional<Metric> ParseMetric(std::string_view name);
const char* MetricName(Metric metric);

struct ScoreWeights {
  double position = 1.0;  // P, 1/m
  double angle = 1.0;     // A, 1/rad
  double joint = 0.0;     // J, 1/rad or 1/m
};

// A trajectory's scores.
struct Score {
  int samples = 0;  // samples compared
  double e_q = 0;
  double position_rms = 0;  // m
  double angle_rms = 0;     // rad
  double joint_rms = 0;
  double weighted = 0;
  double Of(Metric metric) const;
};

// The angle of the rotation between two unit quaternions (w, x, y, z), rad
// in [0, pi]: 2 atan2(|v|, |w|) of q1^-1 q2, accurate near 0 where 2 acos(w)
// is not.
double RotationAngle(const double q1[4], const double q2[4]);

// Sums the errors of one trajectory, sample by sample.
class ScoreAccumulator {
 public:
  explicit ScoreAccumulator(ScoreWeights weights = {}) : weights_(weights) {}
  // One body at one sample: length L_b (m) for e_q; orientations may be null
  // (a body measured without them).
  void AddBody(const double p_sim[3], const double p_meas[3], const double* q_sim,
               const double* q_meas, double length);
  void AddJoint(double q_sim, double q_meas);
  // Closes sample k (at least one body or joint added since the last).
  void EndSample();
  Score Finish() const;

 private:
  ScoreWeights weights_;
  int samples_ = 0;
  // sums over the samples of each sample's mean
  double eq_ = 0, dp2_ = 0, theta2_ = 0, dq2_ = 0;
  // the current sample's sums and counts
  double eq_k_ = 0, dp2_k_ = 0, theta2_k_ = 0, dq2_k_ = 0;
  int bodies_k_ = 0, oriented_k_ = 0, joints_k_ = 0;
  bool oriented_ = false, jointed_ = false;
};

// ---------------------------------------------------------------------------
// Summaries of per-trajectory scores that a reader can weigh: the mean,
// median and 90th percentile, each mean and median with a 95% percentile
// bootstrap interval (Efron & Tibshirani 1993, ch. 13) over trajectories;
// paired differences of two score arrays with their interval; the folds of
// a cross-validation. Pure functions of the arrays and a seed: the same
// numbers to the bit whatever the threads or processes that made the arrays.

// Mean, median and 90th percentile (linear interpolation between order
// statistics) of values; zeros when empty.
struct Distribution {
  double mean = 0, median = 0, p90 = 0;
};
Distribution Distribute(std::vector<double> values);

// The p-quantile of sorted values (linear interpolation between order
// statistics, p in [0, 1]); 0 when empty.
double Quantile(const std::vector<double>& sorted, double p);

struct Interval {
  double lo = 0, hi = 0;
  bool Contains(double x) const { return lo <= x && x <= hi; }
};

// 2000 resamples: the 2.5% and 97.5% points of the resampled statistic then
// move by about 1% of the interval's width between seeds (Efron &
// Tibshirani's rule: 1000-2000 for percentile intervals).
inline constexpr int kBootstrapResamples = 2000;
inline constexpr double kConfidence = 0.95;

// Distribute's numbers, and an interval for the mean and the median: the
// percentile bootstrap, `resamples` resamples of the values with replacement
// drawn from seed (the same seed and count, the same resamples: two arrays
// of one length are resampled alike).
struct Summary {
  int count = 0;
  Distribution value;
  Interval mean, median;
};
Summary Summarize(const std::vector<double>& values, uint64_t seed,
                  int resamples = kBootstrapResamples);

// The mean of a[i] - b[i] and its percentile bootstrap interval (pairs
// resampled together). An interval that contains 0: the arrays' means are
// not told apart at that confidence.
struct PairedDifference {
  double mean = 0;
  Interval interval;
  bool Distinguishable() const { return !interval.Contains(0.0); }
};
// Throws Error when a and b differ in length.
PairedDifference ComparePaired(const std::vector<double>& a, const std::vector<double>& b,
                               uint64_t seed, int resamples = kBootstrapResamples);

// The mean of values without the floor(trim n) largest (trim in [0, 0.5)),
// summed smallest first: a robust mean that a few outliers cannot carry
// (a cube toss that lands on another face scores about 50 times a typical
// one). Throws Error for a trim outside [0, 0.5).
double TrimmedMean(std::vector<double> values, double trim);

// TrimmedMean of values and its percentile bootstrap interval, from the
// resamples Summarize draws with the same seed and count.
struct Estimate {
  double value = 0;
  Interval interval;
};
Estimate SummarizeTrimmed(const std::vector<double>& values, double trim, uint64_t seed,
                          int resamples = kBootstrapResamples);

// ComparePaired for trimmed means: TrimmedMean(a) - TrimmedMean(b), and the
// interval of that difference over resampled pairs (trim 0: ComparePaired).
PairedDifference ComparePairedTrimmed(const std::vector<double>& a, const std::vector<double>& b,
                                      double trim, uint64_t seed,
                                      int resamples = kBootstrapResamples);

// The fold (0 .. folds - 1) of each of count items: a seeded shuffle dealt
// in turn, so fold sizes differ by at most one. Throws Error unless
// 2 <= folds <= count.
std::vector<int> AssignFolds(int count, int folds, uint64_t seed);

namespace internal {
class Binding;  // ident/binding.h: the data's columns bound to the scene
// ident/work_spread.h: work items spread over the processes of a cluster job
// (the program's MPI ranks)
class WorkSpread;
}  // namespace internal

// Where a trajectory's simulation starts.
enum class StartRule {
  kFirst,  // its first sample, with its measured velocities
  // the published refit of the cube tosses (Acosta, Yang & Posa 2022): the
  // sample `lead` before the first where the first measured free body's z
  // is at or below `height`; when that index is at least `min_samples`, its
  // velocities are refit from the samples before it (RefitRule)
  kRefit,
};

// kRefit's rule. With idx the start sample and t_k the sample times:
//   angular velocity (body frame): the rotation from sample 0 to sample idx
//     over t_idx - t_0;
//   linear velocity across gravity: the mean of the measured velocities over
//     samples 0..idx-1 (the least-squares slope of the positions when no
//     velocity is measured);
//   along gravity: the least-squares line through p + g t^2 / 2 over
//     samples 0..idx-1, its rate at t_(idx-1) (taken at idx, as published).
struct RefitRule {
  // m; default: the body's bounding radius (MuJoCo's rbound of its geoms):
  // the height at which it can first touch a plane at z = 0
  std::optional<double> height;
  int lead = 3;         // samples, >= 0
  int min_samples = 4;  // >= 2
};

// A change to the compiled scene that identification may need beside the
// tags (fit.h names them as parameters).
struct ModelEdit {
  enum class Kind {
    kMassScale,     // a body's mass times value
    kInertiaScale,  // a body's principal inertia times value
    kOffset,        // a geom moved by value (m) along its own z axis (a plane's normal)
    kMujocoTimeconst, kMujocoDampratio,           // every geom's solref
    kMujocoDmin, kMujocoDmax, kMujocoWidth,       // every geom's solimp
    kMujocoFriction,                              // every geom's sliding friction
  };
  Kind kind = Kind::kMassScale;
  int id = -1;  // the body or geom (kMassScale, kInertiaScale, kOffset)
  double value = 1.0;
};

// Applies edits to m (a copy of the scene's model).
void ApplyEdits(mjModel* m, const std::vector<ModelEdit>& edits);

struct ReplayOptions {
  SimulationOptions simulation;  // overrides, fixed timestep, integrator
  std::optional<AutoTimestepOptions> auto_timestep;  // else the fixed timestep
  std::vector<ModelEdit> edits;
  StartRule start = StartRule::kFirst;
  RefitRule refit;
  ScoreWeights weights;
  // e_q's length L_b, m; default: each body's GeomSize (a box's half side)
  std::optional<double> length;
  int jobs = 1;
  // Trajectories spread over processes too (each computes its share, every
  // process gets every result): the program's; null, as a library user
  // leaves it: this process replays them all.
  internal::WorkSpread* spread = nullptr;
  // Called between steps: true stops the replay (the trajectories not
  // finished are marked so).
  std::function<bool()> should_stop;
  bool keep_trajectories = false;  // ReplayedTrajectory::simulated
};

struct ReplayedTrajectory {
  using Status = RunStatus;  // kComplete, kDiverged or kInterrupted
  Status status = Status::kComplete;
  int start = 0;  // the sample the simulation started from
  // Against samples start .. last; a diverged simulation keeps its last
  // finite state for the samples after it.
  Score score;
  double diverged_at = 0;  // s after the start, with kDiverged
  // With SimulationOptions::settle: the bodies in contact at the start state
  // that Settle moved into their static equilibrium, and the farthest move, m.
  int settled_bodies = 0;
  double settled_distance = 0;
  // The simulated state at the last sample compared, the data's columns
  // (fit.h's resting and final-pose gaps).
  std::vector<double> last;
  // With keep_trajectories: samples start .. last, the data's columns.
  std::vector<double> simulated;
};

class Replay {
 public:
  // Binds the data's columns to the scene. Throws Error naming the file and
  // column: a body or joint the scene lacks, a quantity it cannot have, a
  // column group given in part (x without y), a measured body without a
  // free joint or without its orientation.
  Replay(const Scene& scene, const MeasuredData& data);
  ~Replay();
  Replay(const Replay&) = delete;
  Replay& operator=(const Replay&) = delete;

  // Simulates and scores every trajectory. Throws Error when the options are
  // refused (the tags with the overrides, a refit on a scene without a free
  // measured body).
  std::vector<ReplayedTrajectory> Run(const ReplayOptions& options) const;

  // The start sample of trajectory i under options' rule.
  int StartSample(int i, const ReplayOptions& options) const;

  const MeasuredData& data() const { return data_; }

 private:
  class Rollout;

  const Scene& scene_;
  const MeasuredData& data_;
  std::unique_ptr<const internal::Binding> binding_;
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_REPLAY_H_
