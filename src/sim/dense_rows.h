// Copyright contactlaws authors.
//
// DenseRows: trajectory rows inside the steps of the contact-aware timestep,
// so that a sample time does not end a step (Advance). Each step that
// reaches a sample time is bracketed by two exact states (mj_forward at its
// start and its end, the start reused from the step before when that one was
// bracketed too); a row between them is interpolated:
//   - hinge and slide coordinates, and a free joint's position: the cubic
//     Hermite through the ends' qpos and qvel; every dof's velocity: the
//     cubic Hermite through the ends' qvel and qacc (exact for a parabola:
//     free flight under gravity);
//   - a quaternion (free and ball joints): q0 exp(phi(s)), phi the cubic
//     Hermite from 0 to the rotation q0^-1 q1 (as a rotation vector, of the
//     angles q1 allows the one nearest the ends' angular velocities' turn:
//     free flight's long steps turn a spinning body past half a turn) with
//     the ends' angular velocities in q0's frame as its derivatives (exact
//     for a rotation about a fixed axis), normalized by the kinematics that
//     read it; the step's rotation and end velocity once per step;
//   - the kinematics (positions, orientations, point velocities) and the
//     ledger's kinetic and potential energy from that state: MuJoCo's
//     stages, or, when every moving body is a single free body (a scene of
//     balls, dice, a pile), each body's own (FreeBodyKinematics: 23 thousand
//     instructions a row of 49 balls, against 100 thousand for MuJoCo's
//     four stages);
//   - the laws' elastic energy and the ledger's dissipated energy: cubic
//     Hermites through the ends' values and powers (the springs' elastic
//     force times d', DissipatedPower), so that the ledger's total keeps
//     the integration's accuracy inside a step; the friction springs'
//     energy (and its share of the dissipated) linear;
//   - the tags' readings: a depth in contact at both ends the Hermite
//     through depth and depth rate; depth rate, force and friction linear
//     between the ends' exact values. Out of contact both ends read 0 (the
//     auto timestep ends a step just past a touch: no contact begins and
//     ends inside one); in contact a step is at most the fine step t_c / N,
//     so the chord misses the force's curve by at most (pi / N)^2 / 8 of
//     its peak: 4.9e-4 at the default accuracy (N = 50), 7.8e-6 at 1e-5
//     (N = 397): within the accuracy asked. A settled contact (6 steps per
//     duration, auto_timestep.h) has a force that barely changes.
// A row at a step's end is the exact state's, as Simulation::Sample's.

#ifndef CONTACTLAWS_SIM_DENSE_ROWS_H_
#define CONTACTLAWS_SIM_DENSE_ROWS_H_

#include <optional>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/contact_model.h"
#include "contactlaws/simulation.h"

namespace contactlaws {

class DenseRows {
 public:
  explicit DenseRows(Simulation* sim);

  // Before a step that reaches a sample time: its start state (mj_forward,
  // unless the last End() was at this time).
  void Start();
  // After that step: its end state (mj_forward).
  void End();
  // The row at time t within [the start, the end]: the end's exact row
  // when t is within tolerance (s) of it, else interpolated.
  void Row(double t, double tolerance, std::vector<double>* row);

 private:
  // One exact state: after mj_forward on the simulation's data.
  struct State {
    double time = -1;
    std::vector<mjtNum> qpos, qvel, qacc;
    std::vector<TagReading> readings;
    double spring = 0;            // J, the laws' springs (ContactData::LawEnergy)
    double spring_rate = 0;       // W, its rate: the springs' force times d'
    double friction_spring = 0;   // J, the friction springs
    double dissipated = 0;        // J, the ledger's
    double dissipated_power = 0;  // W, DissipatedPower
  };
  void Capture(State* state);
  // scratch_'s qpos and qvel at time t, and their kinematics
  void Interpolate(double t);
  // turns_ for the step from start_ to end_
  void Turns();

  Simulation* sim_;
  const bool free_bodies_;  // OnlySingleFreeBodies: FreeBodyKinematics suffices
  UniqueData scratch_;      // the interpolated state
  std::optional<double> kinetic_;  // J, FreeBodyKinematics's, else from scratch_'s mass matrix
  State start_;
  State end_;
  std::vector<TagReading> readings_;  // interpolated
  // Each rotation joint's turn over the step, the same for every row in it:
  // the rotation vector of q0^-1 q1 and the end's angular velocity in q0's
  // frame (6 numbers a joint, in joint order); current until the next End().
  std::vector<mjtNum> turns_;
  bool turns_current_ = false;
  std::vector<mjtNum> kept_positions_;  // Capture's qpos, kept through its forward pass
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_DENSE_ROWS_H_
