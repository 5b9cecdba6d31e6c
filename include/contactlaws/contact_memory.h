// Copyright contactlaws authors.
//
// Per-contact memory, without MuJoCo types: what the hooks evaluated at each
// contact point, the episodes of every point (first touch to separation), the
// energy the laws dissipated, and why a run stopped. ContactData (MuJoCo
// side) fills these once per accepted step; nothing here reads a simulation.

#ifndef CONTACTLAWS_CONTACT_MEMORY_H_
#define CONTACTLAWS_CONTACT_MEMORY_H_

#include <algorithm>
#include <limits>
#include <cstdint>
#include <string>
#include <vector>

namespace contactlaws {

// The friction state of one contact point (friction.h), what the hook
// captured at a step's start and the step commits: the stick springs (or
// LuGre's bristles) and where they are anchored. The anchors are the
// point's body-frame positions (PointEvaluation::local) and the bodies'
// orientations, so that a stage reads its spring's stretch from its own
// positions (RK4 included).
struct FrictionState {
  double spring[3] = {0, 0, 0};  // spring force on body[1] (N), or LuGre's z (m); world
  double torque[3] = {0, 0, 0};  // rolling + torsional spring torque on body[1], N m
  double stiffness = 0;          // k_t at the commit, N/m
  double torque_stiffness[2] = {0, 0};  // torsional, rolling, N m/rad
  bool sliding = false;
  bool torque_sliding[2] = {false, false};  // torsional, rolling
  double orientation[2][4] = {{1, 0, 0, 0}, {1, 0, 0, 0}};  // the bodies' quaternions
};

// One contact point as the hook last saw it (depth > 0).
struct PointEvaluation {
  int pair = -1;     // ContactModel::pairs() index
  int tag = -1;      // ContactModel::tags() index of the pair
  // The open episode of this physical point (EpisodeLog index), found by where
  // the point sits on the two bodies; -1: none, this evaluation is its touch.
  int episode = -1;
  bool touch = false;  // episode < 0
  // a touch with no earlier state: the contact was there when the run (or the
  // memory) started; it touched at that time, at its rate then
  bool at_start = false;
  double depth = 0;
  double depth_rate = 0;
  double impact_velocity = 0;  // the law's v0 (floored; Impact::max_approach_velocity)
  double max_approach = 0;     // the episode's largest d' so far, this one included
  double touch_velocity = 0;   // touch: d' at the step before first touch
  double touch_power = 0;      // touch: the law's dissipated power at touch, W
  double force = 0;
  double elastic_energy = 0;
  double dissipated_power = 0;
  double pos[3] = {0, 0, 0};     // contact point, world frame
  double normal[3] = {0, 0, 0};  // from geom[0] to geom[1]
  // the contact point in the frames of the pair's two bodies (body[0],
  // body[1]): what identifies it from one step to the next
  double local[2][3] = {{0, 0, 0}, {0, 0, 0}};
  // friction (all zero for friction=none): the force and torque on body[1]
  // (body[0] gets their opposites), at pos
  double friction[3] = {0, 0, 0};         // N
  double friction_torque[3] = {0, 0, 0};  // N m
  double friction_energy = 0;  // J, stored by the stick springs (or bristles)
  // W, the power friction takes from the bodies: -F.slip - T.spin. Less what
  // the springs store, it is dissipated (DissipationLedger): sliding under a
  // rising load stretches the spring, so -F.slip alone would count too much.
  double friction_power = 0;
  double slip[3] = {0, 0, 0};   // m/s, body[1] relative to body[0] at pos, tangential
  double spin[3] = {0, 0, 0};   // rad/s, body[1] relative to body[0]
  FrictionState friction_state;  // to commit
};

// Impact::chained: how much faster than its touch a contact must be
// compressed to be a pulse through touching bodies (the cradles' are hundreds
// of times; gravity's rise during an impact stays well below twice).
inline constexpr double kChainFactor = 2.0;

// One contact episode of one contact point: first touch to separation.
struct Impact {
  int tag = -1;             // ContactModel::tags() index
  int pair = -1;            // ContactModel::pairs() index
  int index = 0;            // 1 for the tag's first episode, 2 for its second ...
  int points = 1;           // most points in contact at once (a collision; 1 for a point)
  double time_contact = 0;  // s, extrapolated to d = 0
  // d' of the last state before first touch, m/s (> 0): the approach no
  // contact force has slowed yet (a fixed step finds a contact a fraction of
  // a step late, when a force that jumps at d = 0+ has acted for part of it)
  double impact_velocity = 0;
  bool open = true;               // still in contact
  double time_separation = 0;     // s, extrapolated to d = 0 (closed only)
  double separation_velocity = 0; // -d' of the first state after it, m/s (closed only)
  double max_depth = 0;           // m
  double max_force = 0;           // N
  // The largest approach rate d' while in contact, m/s, the touch's among
  // them: an impact's is its touch speed (its rate only falls once its force
  // acts); a contact between bodies that touched slowly before a pulse came
  // through them (a chain: Newton's cradle) reaches far more. The laws take
  // it as their v0 once it exceeds the touch speed, so that d'/v0 stays
  // below 1 and the law does not turn plastic (d'/v0 in the hundreds).
  double max_approach_velocity = 0;
  // The law's v0 at the touch: impact_velocity raised to the pair's
  // min_impact_velocity (for a collision, the largest of its points' at
  // their touches: a corner that lands after the first is a touch too).
  double touch_v0 = 0;
  // A collision (CollisionLog): one of its points was chained. A collision's
  // rates mix its points: a second corner that lands faster than the first
  // touched raises its largest approach, and is no chain.
  bool points_chained = false;
  // A contact there when the run began (PointEvaluation::at_start): the
  // largest approach rate of its first compression, m/s: the bodies placed
  // touching sinking into their contact's spring, which is neither an
  // impact nor a pulse (0 for a contact that touched during the run).
  double settling_velocity = 0;
  // Compressed more than kChainFactor times faster than the law's v0 at its
  // touch and than its settling (a pulse through touching bodies), or, a
  // collision, one of its points was. Gravity alone raises an impact's rate
  // after the touch (the paper's ball by 5e-6 of 4.2 m/s, a slow one by tens
  // of percent): that is no chain; neither is a contact that opened at rest
  // and settles within the v0 floor, nor one there at the start that settles.
  bool chained() const {
    return points_chained ||
           max_approach_velocity >
               kChainFactor * std::max({impact_velocity, touch_v0, settling_velocity});
  }
  // Whether the bodies approached at all: a contact placed there at t = 0 and
  // pushed apart at once (bodies overlapping) has no approach, and its
  // rebound no restitution.
  bool approached() const { return std::max(impact_velocity, max_approach_velocity) > 0; }
  // separation / the largest approach speed (closed only): an impact's touch
  // speed, a chained contact's pulse
  double restitution_post() const {
    return separation_velocity / std::max(impact_velocity, max_approach_velocity);
  }
  // The tangential side: the slip speed of the contact point (m/s) at the
  // first evaluation in contact and at the last (closed only), and the
  // relative spin about the axis n x t (rad/s, t the direction of the first
  // slip; > 0 rolls along t) at both.
  double tangential_impact_velocity = 0;
  double tangential_separation_velocity = 0;
  double spin_before = 0;
  double spin_after = 0;
  double tangent[3] = {0, 0, 0};  // t, the first slip's direction (0 when none)
  double normal[3] = {0, 0, 0};   // n at the first evaluation
  // tangential separation / impact speed (closed only)
  double tangential_restitution() const {
    return tangential_impact_velocity > 0 ? tangential_separation_velocity / tangential_impact_velocity
                                          : 0.0;
  }
};

// The largest force of a contact from its samples (once per step, at the
// step's start): the largest sample and, where a sample is at least its two
// neighbours, the vertex of the parabola through the three, the peak between
// samples. A sample misses a smooth peak by O(h^2) of it, the vertex by
// O(h^3): the peak force then meets the accuracy of the rebound at the same
// step (auto_accuracy_test).
class PeakForce {
 public:
  void Add(double t, double force);
  double peak() const { return peak_; }

 private:
  double time_[2] = {0, 0};
  double force_[2] = {0, 0};
  int count_ = 0;
  double peak_ = 0;
};

// The tangential slip speed along t and spin about n x t of a point, for an
// Impact's tangential side.
void TangentialSide(const PointEvaluation& e, const double tangent[3], const double normal[3],
                    double* slip, double* spin);

// The time a point touched, extrapolated back from its first evaluation at t:
// the depth was reached at the mean of the touch and current rates; t itself
// for a contact there at the start (PointEvaluation::at_start), and when the
// rates give no time. No earlier than previous, the last commit, where the
// point was not in contact (two cubes falling together touch at a relative
// rate of 1e-21 m/s: extrapolated, 8 ms before the run began).
double TouchTime(const PointEvaluation& e, double t, double previous);

// Sum of the dissipated power of points (contact laws and friction), W.
double DissipatedPower(const std::vector<PointEvaluation>& points);

// The episodes of every contact point, committed once per accepted step. A
// point is the same physical point from one step to the next when it sits
// where an open episode's point sat on either of the pair's two bodies
// (MatchOpenEpisode), whatever order the narrowphase lists it in. A pair
// whose narrowphase returns one point has one contact: its point is its open
// episode's wherever it moved (MuJoCo's general convex collider puts the
// point of a face on a face anywhere on it, from one step to the next).
class EpisodeLog {
 public:
  // points_per_pair: the most points each pair can have at once (its size is
  // the pair count); tags: the tag count.
  EpisodeLog(const std::vector<int>& points_per_pair, int tags);

  // Forgets every episode.
  void Reset();

  // The open episode of pair whose point sat nearest to local (the point in
  // the pair's two body frames), within tolerance (m) in either body's frame,
  // and not yet taken: *taken has a bit per open episode of the pair (in
  // OpenEpisodes order), set here for the one returned; for a pair of one
  // point, its open episode, at any distance. -1 when none.
  int MatchOpenEpisode(int pair, const double local[2][3], double tolerance,
                       uint64_t* taken) const;

  // The largest approach rate committed for an open episode, m/s.
  double MaxApproach(int episode) const { return impacts_[episode].max_approach_velocity; }
  // The committed friction state of an open episode, and where its point
  // sat on the two bodies at that commit (the stick anchors).
  const FrictionState& CommittedFriction(int episode) const { return tracks_[episode].friction; }
  const double (&Anchors(int episode) const)[2][3] { return tracks_[episode].local; }
  const double (&CommittedNormal(int episode) const)[3] { return tracks_[episode].last_normal; }

  // The open episodes of pair (indices in impacts()).
  const std::vector<int>& OpenEpisodes(int pair) const { return pair_open_[pair]; }

  // Opens an episode for each touch point and advances the open ones with
  // the points evaluated at the step's start state, time t.
  void Commit(double t, const std::vector<PointEvaluation>& points);

  // Closes the episodes whose point was not in the last Commit. For each,
  // separation_speed(pair, pos, normal, last_rate) gives -d' of the first
  // state out of contact at the point and normal last in contact.
  template <typename SeparationSpeed>
  void CloseVanished(SeparationSpeed&& separation_speed);

  // The episodes the last CloseVanished closed (indices in impacts()).
  const std::vector<int>& closed() const { return closed_; }

  // Every episode so far, in order of first touch.
  const std::vector<Impact>& impacts() const { return impacts_; }

 private:
  // What matching and closing an episode need beyond Impact.
  struct Track {
    int64_t last_commit = -1;  // the commit that last saw it in contact
    double last_time = 0;
    double last_depth = 0;
    double last_rate = 0;
    PeakForce force;
    double last_pos[3] = {0, 0, 0};
    double last_normal[3] = {0, 0, 0};
    double local[2][3] = {{0, 0, 0}, {0, 0, 0}};  // where it sat on the bodies
    FrictionState friction;
    // there at the start and in its first compression: its rate raises
    // Impact::settling_velocity until it falls below 1 / kChainFactor of it
    bool settling = false;
  };
  void Open(double t, const PointEvaluation& e);
  void Close(int index, double separation_velocity);

  std::vector<std::vector<int>> pair_open_;  // pair -> its open episodes
  std::vector<uint8_t> single_point_;        // pair -> its narrowphase returns one point
  std::vector<int> open_;         // indices of open impacts
  std::vector<int> closed_;       // closed by the last CloseVanished
  std::vector<int> tag_count_;    // episodes per tag
  std::vector<Impact> impacts_;
  std::vector<Track> tracks_;     // parallel to impacts_
  double previous_commit_ = -std::numeric_limits<double>::infinity();  // s, TouchTime's bound
  int64_t commits_ = 0;
};

// The collisions of every pair: from its first point touching to its last
// point leaving, built from the episodes of its points. A collision's impact
// velocity is the largest touch velocity among the points that open it (all
// that touch in its first step); its separation velocity is that of its
// point that leaves last (the largest, if several leave in one step). Its
// max_force is the largest sum of its points' forces at one evaluation, its
// max_depth the deepest point, points the most points in contact at once.
class CollisionLog {
 public:
  // pairs, tags: the pair and tag counts.
  CollisionLog(int pairs, int tags);

  void Reset();

  // After episodes' Commit and CloseVanished with the same points, time t.
  void Commit(double t, const std::vector<PointEvaluation>& points, const EpisodeLog& episodes);

  // Every collision so far, in order of first touch.
  const std::vector<Impact>& impacts() const { return impacts_; }

 private:
  std::vector<int> open_;       // pair -> its open collision, or -1
  std::vector<uint8_t> seen_;   // pair -> in contact at this commit (scratch)
  std::vector<int> tag_count_;  // collisions per tag
  std::vector<PeakForce> force_;  // pair -> the peak of its open collision
  std::vector<Impact> impacts_;
  double previous_commit_ = -std::numeric_limits<double>::infinity();  // s, TouchTime's bound
};

// The energy the laws dissipated: the trapezoid of their power over the
// committed steps.
class DissipationLedger {
 public:
  void Reset();

  // Adds the step that ends at t, whose start state's points are points. A
  // touch point's power acted from its touch, where a law whose force jumps
  // at d = 0+ (Kelvin-Voigt) already dissipates: its trapezoid spans
  // [touch, t] with the touch's power, not [previous commit, t] from zero.
  void Commit(double t, const std::vector<PointEvaluation>& points);

  // J, up to the latest evaluation (points, at time t): the laws' dissipated
  // power and friction's power on the bodies, integrated, less the energy the
  // friction springs of points hold now.
  double Dissipated(double t, const std::vector<PointEvaluation>& points) const;

 private:
  bool has_committed_ = false;
  double committed_time_ = 0;
  double committed_power_ = 0;
  double dissipated_ = 0;
};

// Why a run cannot go on: found after a step, kept until the memory is reset.
struct Divergence {
  enum class Kind {
    kNonFinite,     // NaN or infinity in qpos, qvel, qacc or a contact force
    kMujocoReset,   // MuJoCo found a bad qpos/qvel/qacc and reset the data
    kTooDeep,       // a contact deeper than its pair's depth_limit
  };
  Kind kind = Kind::kNonFinite;
  double time = 0;       // s: the start of the step that diverged
  // The deepest tagged contact at that state, relative to its limit (-1: none
  // in contact, or kMujocoReset: the state is lost), its depth and depth rate.
  int pair = -1;
  double depth = 0;        // m
  double depth_rate = 0;   // m/s
  std::string what;        // one phrase: "depth 0.06 m beyond 0.05 m (half ...)"
};

template <typename SeparationSpeed>
void EpisodeLog::CloseVanished(SeparationSpeed&& separation_speed) {
  closed_.clear();
  for (size_t k = 0; k < open_.size();) {
    const int index = open_[k];
    const Track& track = tracks_[index];
    if (track.last_commit == commits_) {
      ++k;
      continue;
    }
    Close(index, separation_speed(impacts_[index].pair, track.last_pos, track.last_normal,
                                  track.last_rate));
    open_[k] = open_.back();
    open_.pop_back();
  }
}

}  // namespace contactlaws

#endif  // CONTACTLAWS_CONTACT_MEMORY_H_
