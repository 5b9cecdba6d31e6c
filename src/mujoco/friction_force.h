// Copyright contactlaws authors.
//
// The friction of a contact point, a part of PointEvaluator: the slip of
// body[1] relative to body[0], the stretch of the stick springs since the
// last committed step (read from the stage's own positions: the anchors are
// points fixed on the two bodies, and the bodies' orientations), the kernels
// of friction.h, and the forces and torques on the two bodies, equal and
// opposite; for condim 4 and 6 the torsional and rolling resistance. A pure
// function of the state it is given and the committed memory, like the
// normal law.

#ifndef CONTACTLAWS_MUJOCO_FRICTION_FORCE_H_
#define CONTACTLAWS_MUJOCO_FRICTION_FORCE_H_

#include <mujoco/mujoco.h>

#include "memory/contact_memory.h"
#include "contactlaws/contact_model.h"

namespace contactlaws::internal {

// The friction at point con of pair, whose normal law e holds (and in
// e->slip, body[1]'s velocity relative to body[0] at the point, as
// PointEvaluator::EvaluatePoint leaves it): records its slip (in the tangent
// plane) and spin in *e, and for a pair with friction adds the friction force
// and torque to d->qfrc_passive and records them in *e, with the state to
// commit (episodes: the committed memory of e's open episode). With
// kRecordOnly the tangential force is recorded and not added (the contact
// steps integrate it inside the step); the rolling and torsional torques are
// added either way.
enum class TangentialForce { kAdd, kRecordOnly };
void AddFriction(const ContactModel& model, mjData* d, const EpisodeLog& episodes,
                 const GeomPair& pair, const mjContact& con, PointEvaluation* e,
                 TangentialForce tangential = TangentialForce::kAdd);

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_MUJOCO_FRICTION_FORCE_H_
