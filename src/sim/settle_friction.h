// Copyright contactlaws authors.
//
// The friction a settled start's contacts carry at t = 0. Settling holds
// each free body where the scene put it along its contact surfaces (its load
// along them cancelled: SettleDirections), so its stick springs end the
// relaxation unloaded. Started so, a body under a tangential load (a box
// pushed along the floor, a block on a slope) first slips until its springs
// take the load, by mu_s F_n / k_t, and loses the friction's impulse over
// that time for good: 1.6e-3 m/s on SimBenchmark's rolling box (mjcf/rolling.xml,
// 2.7e-6 (m/s)^2 over 4 s against the analytic velocities). Instead each
// contact starts with the friction its load asks:
//
// - a body's tangential load T (SettleDirections::Tangential) plus what the
//   bodies it carries pass down to it is shared by its supporting contacts
//   (those whose normal force opposes its load) in proportion to their
//   normal forces: F_i = -T N_i / sum N, stuck, while |T| <= sum mu_s N;
// - beyond that the body slides: F_i = -mu_k N_i T/|T|, sliding.
//
// The bodies are taken from the highest (against gravity) down, so that a
// stack's lower contacts carry what the upper ones pass down. Only the
// stick-spring models (coulomb, stribeck) keep such a state.
//
// Where no body slides, Settle goes on to the static equilibrium (the
// friction's springs in the dynamics, the bodies free to turn and shift by
// their stretch: a block on a slope tips onto its downhill corners under the
// friction below its centre) and starts the contacts with the friction
// they hold there (HeldFriction).

#ifndef CONTACTLAWS_SIM_SETTLE_FRICTION_H_
#define CONTACTLAWS_SIM_SETTLE_FRICTION_H_

#include <vector>

#include "contactlaws/impact.h"
#include "contactlaws/simulation.h"
#include "sim/settle_directions.h"

namespace contactlaws {

// The points of sim's latest evaluation (at the settled state, after
// mj_forward), each with the friction state it starts with as above;
// *sliding: whether a body slides.
std::vector<PointEvaluation> StartFriction(const Simulation& sim,
                                           const SettleDirections& directions, bool* sliding);

// The points of sim's latest evaluation with the friction they hold (after a
// static relaxation, whose stick springs carry the load), as touches at the
// start at rest.
std::vector<PointEvaluation> HeldFriction(const Simulation& sim);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_SETTLE_FRICTION_H_
