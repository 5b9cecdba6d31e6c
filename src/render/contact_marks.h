// Copyright contactlaws authors.
//
// What render draws of the tagged contacts, beside MuJoCo's scene: a small
// disc in the contact plane at each point, and per geom pair an arrow for
// the normal force and one for the friction force, the sums of its points'
// forces at their centre of pressure (a box resting on its four corners gets
// one arrow of its weight, from the middle of its face), on the pair's
// moving body (the force it gets from the other), in colours no body of the
// shipped scenes wears. MuJoCo draws forces only for contacts in its solver,
// so the arrows are ours.
//
// Sizes follow the moving body (MovingBodies::Size): a disc is a tenth of
// it across and never hides the body; an arrow's shaft is 3% of it
// thick; its length is the force times MovingBodies::ArrowScale (the body's
// weight as long as the body) unless --force-scale gives one scale for all,
// and at most kMaxArrowSizes sizes (an impact's peak is a thousand weights).

#ifndef CONTACTLAWS_RENDER_CONTACT_MARKS_H_
#define CONTACTLAWS_RENDER_CONTACT_MARKS_H_

#include <optional>

#include <mujoco/mujoco.h>

#include "contactlaws/simulation.h"
#include "render/moving_bodies.h"

namespace contactlaws::render {

// A default-scaled arrow stops growing at this many body sizes.
constexpr double kMaxArrowSizes = 3.0;

// Appends the marks of sim's latest evaluated points to scene, as many as fit.
// force_scale: m/N for every arrow, unscaled; none: each body's ArrowScale.
void AddContactMarks(const Simulation& sim, const MovingBodies& moving,
                     std::optional<double> force_scale, mjvScene* scene);

}  // namespace contactlaws::render

#endif  // CONTACTLAWS_RENDER_CONTACT_MARKS_H_
