// Copyright contactlaws authors.
//
// What a run records of its contacts, without MuJoCo types: an Episode (one
// stretch of contact, first touch to separation: a pair's impact or a
// point's episode) and a Divergence (why a run cannot go on). ContactData's
// impacts(), point_episodes() and divergence() return them (the vocabulary:
// docs/library.md, "Words").

#ifndef CONTACTLAWS_IMPACT_H_
#define CONTACTLAWS_IMPACT_H_

#include <algorithm>
#include <string>

namespace contactlaws {

// Episode::chained: how much faster than its touch a contact must be
// compressed to be a pulse through touching bodies (the cradles' are hundreds
// of times; gravity's rise during an impact stays well below twice).
inline constexpr double kChainFactor = 2.0;

// One episode of contact, first touch to separation: an impact (a pair's,
// from its first point touching to its last point leaving: ImpactLog) or a
// point episode (one contact point's: EpisodeLog).
struct Episode {
  int tag = -1;             // ContactModel::tags() index
  int pair = -1;            // ContactModel::pairs() index
  int index = 0;            // 1 for the tag's first episode, 2 for its second ...
  int points = 1;           // most points in contact at once (an impact; 1 for a point)
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
  // min_impact_velocity (for an impact, the largest of its points' at
  // their touches: a corner that lands after the first is a touch too).
  double touch_v0 = 0;
  // An impact (ImpactLog): one of its points was chained. An impact's
  // rates mix its points: a second corner that lands faster than the first
  // touched raises its largest approach, and is no chain.
  bool points_chained = false;
  // A contact there when the run began (PointEvaluation::at_start): the
  // largest approach rate of its first compression, m/s: the bodies placed
  // touching sinking into their contact's spring, which is neither an
  // impact nor a pulse (0 for a contact that touched during the run).
  double settling_velocity = 0;
  // Compressed more than kChainFactor times faster than the law's v0 at its
  // touch and than its settling (a pulse through touching bodies), or, an
  // impact, one of its points was. Gravity alone raises an impact's rate
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

}  // namespace contactlaws

#endif  // CONTACTLAWS_IMPACT_H_
