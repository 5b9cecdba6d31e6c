// Copyright contactlaws authors.
//
// Replay: a tagged scene simulated from the start of each measured
// trajectory (MeasuredData) to its last sample, and scored against it
// (score.h). One compiled scene, one Simulation per thread reused across
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

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contactlaws/auto_timestep.h"
#include "contactlaws/measured.h"
#include "contactlaws/score.h"
#include "contactlaws/simulation.h"
#include "contactlaws/statistics.h"

namespace contactlaws {

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
  enum class Status { kComplete, kDiverged, kInterrupted };
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
  // (rest.h's resting and final-pose gaps).
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
