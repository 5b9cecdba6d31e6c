// Copyright contactlaws authors.
//
// Starting at rest: the bodies a scene places touching are moved, before
// t = 0, into the static equilibrium of their contacts, so that the run does
// not begin with every one of them dropping into its penalty springs.
//
// The method is a quasi-static relaxation: from the scene's positions at
// rest, the dynamics (gravity, the laws, friction's stick springs, MuJoCo's
// own forces) are stepped at the scene's timestep with every other body held
// where it is, and the velocities are quenched (set to 0) whenever the
// kinetic energy starts to fall: each quench lands nearer the minimum of the
// potential energy. It ends when the residual acceleration of every moving
// dof at rest is below kSettleResidual. Only the positions change: the
// velocities, the time and everything else are the scene's.
//
// There is no equilibrium when a body would fall (it moves farther than its
// contacts could compress: GeomPair::depth_limit) or slide (a contact point
// sliding at the end, or the relaxation not converging within
// kSettleDuration): Settle refuses in one line.

#ifndef CONTACTLAWS_SIM_SETTLE_H_
#define CONTACTLAWS_SIM_SETTLE_H_

#include "contactlaws/simulation.h"

namespace contactlaws {

// Two tagged geoms this close (m) at the scene's positions are placed
// touching: a placement written to the micrometre, or exactly at d = 0,
// whose rounding leaves either sign.
inline constexpr double kTouchingGap = 1e-6;
// The residual acceleration at rest that ends the relaxation, m/s^2 (rad/s^2
// for a turning dof): 1e-6 of gravity's 9.81. A body released there moves
// by 5e-9 m in its first 0.1 s.
inline constexpr double kSettleResidual = 1e-5;
// The relaxation gives up after this much simulated time, s.
inline constexpr double kSettleDuration = 5.0;

// Moves sim's bodies in contact at its current state into their static
// equilibrium (positions only; sim's data is left there with zero
// velocities and the contact memory as the relaxation left it: Simulation
// resets both). Throws Error "SOURCE: --settle: ..." when there is none, or
// when a body in contact is driven (a contactdrive moves).
SettleReport Settle(Simulation* sim);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_SETTLE_H_
