// Copyright contactlaws authors.
//
// One contact point as the passive hook evaluated it, without MuJoCo types:
// its kinematics, the law's force, the friction and the state to commit
// (ContactData::latest()).

#ifndef CONTACTLAWS_POINT_EVALUATION_H_
#define CONTACTLAWS_POINT_EVALUATION_H_

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
  double impact_velocity = 0;  // the law's v0 (floored; Episode::max_approach_velocity)
  double max_approach = 0;     // the episode's largest d' so far, this one included
  double touch_velocity = 0;   // touch: d' at the step before first touch
  double touch_power = 0;      // touch: the law's dissipated power at touch, W
  double force = 0;
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

}  // namespace contactlaws

#endif  // CONTACTLAWS_POINT_EVALUATION_H_
