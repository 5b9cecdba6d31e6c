// Copyright contactlaws authors.
//
// Tagged contacts made visible to MuJoCo: the contact points of the tagged
// pairs are not in d->contact (the contact filter discards those pairs, so
// that MuJoCo makes no constraint for them), and MuJoCo's visualisation
// (mjv_updateScene with mjVIS_CONTACTPOINT) draws only what d->contact lists.
// AppendVisibleContacts appends them after a step (ContactData::AfterStep
// calls it), excluded from the solver
// (exclude = 1, "in gap", efc_address = -1), as MuJoCo itself lists a contact
// within a geom's gap: mjv_updateScene draws the point in the contactgap
// colour and no force (the force is ours, not the solver's). The next
// mj_collision (the next mj_step or mj_forward) clears them with the rest of
// the list.

#ifndef CONTACTLAWS_MUJOCO_VISIBLE_CONTACTS_H_
#define CONTACTLAWS_MUJOCO_VISIBLE_CONTACTS_H_

#include <mujoco/mujoco.h>

#include "contactlaws/contact_data.h"

namespace contactlaws {

// Appends each contact point of contacts.latest() (the tagged points of the
// latest hook evaluation, depth > 0) to d->contact, d being contacts' data:
// geoms of its pair, pos, dist = -depth, frame = the normal from geom1 to
// geom2 and two tangents, dim 1, exclude 1, efc_address -1. Returns how many
// were appended. Never writes beyond m->nconmax. Allocates nothing.
int AppendVisibleContacts(const ContactData& contacts, mjData* d,
                          VisibleContactsOverflow* overflow);

}  // namespace contactlaws

#endif  // CONTACTLAWS_MUJOCO_VISIBLE_CONTACTS_H_
