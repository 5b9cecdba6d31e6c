// Copyright contactlaws authors.
//
// Per-contact memory, without MuJoCo types: the episodes of every contact
// point (first touch to separation), the impacts of every pair, and the
// energy the laws dissipated, built from the points the hooks evaluated
// (impact.h's PointEvaluation) into its records. ContactData (MuJoCo
// side) fills these once per accepted step; nothing here reads a simulation.

#ifndef CONTACTLAWS_CONTACT_MEMORY_H_
#define CONTACTLAWS_CONTACT_MEMORY_H_

#include <cstdint>
#include <limits>
#include <vector>

#include "contactlaws/impact.h"

namespace contactlaws {

// The largest force of a contact from its samples (once per step, at the
// step's start): the largest sample and, where a sample is at least its two
// neighbours, the vertex of the parabola through the three, the peak between
// samples. A sample misses a smooth peak by O(h^2) of it, the vertex by
// O(h^3): the peak force then meets the accuracy of the rebound at the same
// step (auto_accuracy_test). Only where the two intervals are within
// kPeakSpacing of each other: a sliver beside a long interval (contact
// steps' sub-samples, one ended just past a touch or at the step's end)
// makes the parabola's curvature the sliver's noise. A 39 ns sub-step after
// a 13 us one put a box_stack.xml contact's peak at 4,167 N, five times its
// largest sample, 752 N.
class PeakForce {
 public:
  static constexpr double kPeakSpacing = 4;

  void Add(double t, double force);
  double peak() const { return peak_; }

 private:
  double time_[2] = {0, 0};
  double force_[2] = {0, 0};
  int count_ = 0;
  double peak_ = 0;
};

// The tangential slip speed along t and spin about n x t of a point, for an
// Episode's tangential side.
void TangentialSide(const PointEvaluation& e, const double tangent[3], const double normal[3],
                    double* slip, double* spin);

// The time a point touched, extrapolated back from its first evaluation at t:
// the depth was reached at the mean of the touch and current rates; t itself
// for a contact there at the start (PointEvaluation::at_start), and when the
// rates give no time. No earlier than previous, the last commit, where the
// point was not in contact (two cubes falling together touch at a relative
// rate of 1e-21 m/s: extrapolated, 8 ms before the run began).
double TouchTime(const PointEvaluation& e, double t, double previous);

// The smallest depth the coordinates resolve at point e, m: 4 eps times the
// largest magnitude among its world position and its positions on the two
// bodies. A depth is a difference of positions (a sphere pair's, of its
// centres' distance and the radii): each is rounded to eps of its size, so a
// depth below this is rounding (bodies placed exactly touching, 0.04 m
// apart: 6.9e-18 m).
double DepthResolution(const PointEvaluation& e);

// Sum of the dissipated power of points (contact laws and friction), W.
double DissipatedPower(const std::vector<PointEvaluation>& points);

// The episodes of every contact point, committed once per accepted step. A
// point is the same physical point from one step to the next when it sits
// where an open episode's point sat on either of the pair's two bodies
// (MatchOpenEpisodes), whatever order the narrowphase lists it in. A pair
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

  // The open episodes of count points of pair at once (local + 6 i: point i
  // in the pair's two body frames, body 0's then body 1's) into episode[i]
  // (-1: none): the nearest point and open episode within tolerance (m, in
  // either frame) first, then the nearest of the rest, each episode to one
  // point (at most the first 64 open); for a pair of one point, its open
  // episode to the first point left without one. A point that appears beside
  // an open one (a face patch's new point) takes no episode from the point
  // nearer to it, whatever order the narrowphase lists the two in.
  void MatchOpenEpisodes(int pair, const double* local, int count, double tolerance,
                         int* episode) const;

  // The largest approach rate committed for an open episode, m/s.
  double MaxApproach(int episode) const { return episodes_[episode].max_approach_velocity; }
  // The committed friction state of an open episode, and where its point
  // sat on the two bodies at that commit (the stick anchors).
  const FrictionState& CommittedFriction(int episode) const { return tracks_[episode].friction; }
  const double (&Anchors(int episode) const)[2][3] { return tracks_[episode].local; }
  const double (&CommittedNormal(int episode) const)[3] { return tracks_[episode].last_normal; }

  // The open episodes of pair (indices in episodes()).
  const std::vector<int>& OpenEpisodes(int pair) const { return pair_open_[pair]; }

  // Opens an episode for each touch point and advances the open ones with
  // the points evaluated at the step's start state, time t.
  void Commit(double t, const std::vector<PointEvaluation>& points);

  // Closes the episodes whose point was not in the last Commit. For each,
  // separation_speed(pair, pos, normal, last_rate) gives -d' of the first
  // state out of contact at the point and normal last in contact.
  template <typename SeparationSpeed>
  void CloseVanished(SeparationSpeed&& separation_speed);

  // The episodes the last CloseVanished closed (indices in episodes()).
  const std::vector<int>& closed() const { return closed_; }

  // Every episode so far, in order of first touch.
  const std::vector<Episode>& episodes() const { return episodes_; }

 private:
  // What matching and closing an episode need beyond Episode.
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
    // Episode::settling_velocity until it falls below 1 / kChainFactor of it
    bool settling = false;
  };
  void Open(double t, const PointEvaluation& e);
  void Close(int index, double separation_velocity);

  std::vector<std::vector<int>> pair_open_;  // pair -> its open episodes
  // MatchOpenEpisodes' scratch: each point's distance to each open episode
  mutable std::vector<double> distances_;
  std::vector<uint8_t> single_point_;        // pair -> its narrowphase returns one point
  std::vector<int> open_;         // indices of open episodes
  std::vector<int> closed_;       // closed by the last CloseVanished
  std::vector<int> tag_count_;    // episodes per tag
  std::vector<Episode> episodes_;
  std::vector<Track> tracks_;     // parallel to episodes_
  double previous_commit_ = -std::numeric_limits<double>::infinity();  // s, TouchTime's bound
  int64_t commits_ = 0;
};

// The impacts of every pair: from its first point touching to its last
// point leaving, built from the episodes of its points. An impact's impact
// velocity is the largest touch velocity among the points that open it (all
// that touch in its first step); its separation velocity is that of its
// point that leaves last (the largest, if several leave in one step). Its
// max_force is the largest sum of its points' forces at one evaluation, its
// max_depth the deepest point, points the most points in contact at once.
class ImpactLog {
 public:
  // pairs, tags: the pair and tag counts.
  ImpactLog(int pairs, int tags);

  void Reset();

  // After episodes' Commit and CloseVanished with the same points, time t.
  void Commit(double t, const std::vector<PointEvaluation>& points, const EpisodeLog& episodes);

  // Every impact so far, in order of first touch; an impact that closed
  // without its depth ever resolved (Episode::resolved) is not one.
  const std::vector<Episode>& impacts() const { return impacts_; }

 private:
  // Removes impacts_[index], numbering the tag's later impacts down.
  void Drop(int index);

  std::vector<int> open_;       // pair -> its open impact, or -1
  std::vector<uint8_t> seen_;   // pair -> in contact at this commit (scratch)
  std::vector<int> tag_count_;  // impacts per tag
  std::vector<PeakForce> force_;  // pair -> the peak of its open impact
  std::vector<Episode> impacts_;
  double previous_commit_ = -std::numeric_limits<double>::infinity();  // s, TouchTime's bound
};

// The energy the laws dissipated, booked step by step.
class DissipationLedger {
 public:
  // How a step's share is booked.
  enum class Booking {
    // The trapezoid of the power at the step's two ends: a step whose
    // integrator follows the force through it (RK4's stages).
    kTrapezoid,
    // A step that holds each force from its start state through the step
    // (MuJoCo's Euler and implicit integrators: the laws' forces are
    // explicit): the damping and friction forces of the start times the
    // mean of the point's rates (depth rate, slip, spin) at the start and
    // the end, the work the velocity update did with them (Delta K = h f .
    // (v0 + v1) / 2). The trapezoid of the end's power would book, over a
    // contact, h / 2 times the integral of F' v too much: first order in the
    // step (3.4% of a hinged plank's landing at --accuracy 1e-3).
    kHeldForce,
  };

  void Reset();

  // Adds the step that ends at t, whose start state's points are points,
  // booked as booking says. A touch point's power acted from its touch,
  // where a law whose force jumps at d = 0+ (Kelvin-Voigt) already
  // dissipates: its trapezoid spans [touch, t] with the touch's power, not
  // [previous commit, t] from zero.
  void Commit(double t, const std::vector<PointEvaluation>& points,
              Booking booking = Booking::kTrapezoid);

  // Adds energy (J) dissipated over the committed steps beyond what their
  // booking took: an integrator's own quadrature of the power against the
  // trapezoid (ContactStepper::dissipation_correction).
  void Book(double energy) { dissipated_ += energy; }
  // Books energy (J) at the next Commit less half_step (s) times the laws'
  // dissipated power there of the point of episode (none: 0): the end of
  // a trapezoid the next Commit closes, replaced by an integrator's own
  // quadrature (ContactStepper::LastSubStep).
  void Defer(int episode, double energy, double half_step) {
    deferred_.push_back({episode, energy, half_step});
  }

  // J, up to the latest evaluation (points, at time t): the laws' dissipated
  // power and friction's power on the bodies, integrated, less the energy the
  // friction springs of points hold now.
  double Dissipated(double t, const std::vector<PointEvaluation>& points) const;

 private:
  // A point of the last commit that held a damping force through the step
  // after it (kHeldForce).
  struct HeldForce {
    int episode;
    double damping;    // N, the law's damping force along the normal
    double friction[3];  // N, PointEvaluation::friction
    double torque[3];    // N m, PointEvaluation::friction_torque
  };

  struct Deferred {
    int episode;
    double energy;     // J
    double half_step;  // s
  };
  std::vector<Deferred> deferred_;
  bool has_committed_ = false;
  double committed_time_ = 0;
  double committed_power_ = 0;
  double dissipated_ = 0;
  std::vector<HeldForce> held_;
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
    Close(index, separation_speed(episodes_[index].pair, track.last_pos, track.last_normal,
                                  track.last_rate));
    open_[k] = open_.back();
    open_.pop_back();
  }
}

}  // namespace contactlaws

#endif  // CONTACTLAWS_CONTACT_MEMORY_H_
