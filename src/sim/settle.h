// Copyright contactlaws authors.
//
// Starting in contact: the bodies a scene places touching are moved, before
// t = 0, to the depth where their contacts carry their load (the normal
// equilibrium of their contacts), so that the run does not begin with every
// one of them dropping into its penalty springs. Their positions along the
// contact surfaces, their velocities, the time and everything else are the
// scene's: a body pushed along the surface (an actuator, an applied force, a
// slope steeper than its friction) starts at its depth and slides in the run,
// and one whose contacts carry its weight and not its turn (a ball on a
// slope, a domino tilted on an edge) starts there and rolls or tips
// (SettleReport::unheld names it).
//
// The method is a quasi-static relaxation: from the scene's positions at
// rest, the dynamics (gravity, the scene's actuator and applied forces, the
// laws, friction's stick springs, MuJoCo's own forces) are stepped under
// Euler (Simulation sets it: one evaluation a step, at the positions the
// relaxation projects; RK4's later stages would see the bodies slid along
// their surfaces within the step and friction's springs stretched by it: an
// offset cube on a cube kept turning at 4 rad/s^2 at 1e-4 s, 0.4 at 1e-5 s,
// and was refused as tipping) at the run's timestep, shortened where the auto
// timestep's rules ask (a scene at MuJoCo's 2 ms, with contacts explicit
// while it relaxes), with every other body held where it is and each free body
// in contact moved along its contacts' normals only (SettleDirections: it
// tilts onto its points, it does not slide or spin in the surface), and the
// velocities are quenched (set to 0) whenever the kinetic energy starts to
// fall: each quench lands nearer the minimum of the potential energy. It
// ends when the residual acceleration of every moving dof at rest, in those
// directions, is below kSettleResidual. A body's load reaches the bodies
// below it through their contacts, so each sinks under the bodies above it.
//
// Settle refuses in one line, naming the body, one that no contact carries:
// its load along its contact surfaces (a ball touching a wall beside it), or
// moved farther than its contacts could compress (GeomPair::depth_limit)
// before they carried it; and a body touching a contactdrive's body, whose
// prescribed motion leaves no equilibrium at rest.

#ifndef CONTACTLAWS_SIM_SETTLE_H_
#define CONTACTLAWS_SIM_SETTLE_H_

#include <vector>

#include "contactlaws/impact.h"
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
// A free body's contacts carry its load when at least this fraction of it
// lies along their normals: the relaxation's own residual, kSettleResidual,
// relative to gravity's 9.81 m/s^2. Below it, the load is along the contact
// surfaces up to rounding and the body would fall past them.
inline constexpr double kSettleCarried = 1e-6;
// The relaxation gives up after this much simulated time, s.
inline constexpr double kSettleDuration = 5.0;

// Moves sim's bodies in contact at its current state into the normal
// equilibrium of their contacts (positions only; sim's data is left there
// with zero velocities and the contact memory as the relaxation left it:
// Simulation resets both). Throws Error "SOURCE: --settle: ..." naming a body
// no contact carries, or one touching a contactdrive's body. start_contacts, when
// given: the settled state's contact points with the friction they carry at
// t = 0 (settle_friction.h), for ContactData::StartWith.
SettleReport Settle(Simulation* sim, std::vector<PointEvaluation>* start_contacts = nullptr);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_SETTLE_H_
