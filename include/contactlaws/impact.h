// Copyright contactlaws authors.
//
// What a run records of its contacts, without MuJoCo types: each contact
// point as the hooks last evaluated it (PointEvaluation, FrictionState), an
// Episode (one stretch of contact, first touch to separation: a pair's
// impact or a point's episode) and a Divergence (why a run cannot go on).
// ContactData's latest(), impacts(), point_episodes() and divergence()
// return them (the vocabulary: docs/library.md, "Words").

#ifndef CONTACTLAWS_IMPACT_H_
#define CONTACTLAWS_IMPACT_H_

#include <algorithm>
#include <string>

namespace contactlaws {

// ---------------------------------------------------------------------------
// One contact point as the passive hook evaluated it, without MuJoCo types:
// its kinematics, the law's force, the friction and the state to commit
// (ContactData::latest()).

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
  // the point's share of its contact's force (a face patch's points share
  // the patch's: docs/geometry.md); force, dissipated and touch power,
  // elastic energy and the friction's springs are the law's times weight
  double weight = 1;
  double impact_velocity = 0;  // the law's v0 (floored; Episode::max_approach_velocity)
  double max_approach = 0;     // the episode's largest d' so far, this one included
  double touch_velocity = 0;   // touch: d' at the step before first touch
  double touch_power = 0;      // touch: the law's dissipated power at touch, W
  double force = 0;
  double dissipated_power = 0;
  double pos[3] = {0, 0, 0};     // contact point, world frame
  double normal[3] = {0, 0, 0};  // from geom[0] to geom[1]
  // the direction the law's force pushes body[1] along, per newton of it:
  // the gradient of the depth (the normal, but at a face patch's point that
  // slides along an edge: geometry/patch.h, ClipVertex), its component along
  // the normal 1
  double gradient[3] = {0, 0, 0};
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
  // Its depth exceeded, at some commit, what the coordinates resolve at its
  // point (DepthResolution, contact_memory.h). An episode that never did is
  // rounding, not a contact (bodies placed exactly touching, nudged by
  // forces of 1e-17 N that no position can show): a closed impact of that
  // kind is dropped from impacts(), and point_episodes() keeps such points
  // for their memory but the reports leave them out.
  bool resolved = false;
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
