// Copyright contactlaws authors.
//
// What a scene's mjData needs: MuJoCo 2.2.2 sizes the data's arena by its
// defaults (njmax = 500 constraint rows: 3 MB zeroed by mj_makeData and every
// mj_resetData; nstack from a heuristic on njmax), whatever the scene. A
// scene whose every collidable pair is tagged makes no contact constraint,
// so its rows are bounded by its equality constraints, friction losses and
// limits.

#ifndef CONTACTLAWS_SIM_ARENA_H_
#define CONTACTLAWS_SIM_ARENA_H_

#include <mujoco/mujoco.h>

#include "contactlaws/contact_model.h"

namespace contactlaws {

// True when MuJoCo may make a contact constraint: an explicit <contact><pair>,
// or two geoms that MuJoCo's own filter lets collide and no tag claims.
bool HasUntaggedContacts(const ContactModel& cm);

// Sizes m's arena to the scene before mj_makeData: njmax to the rows it can
// need, nstack by MuJoCo's own heuristic for that njmax plus what the
// passive hook takes. Only when both are MuJoCo's defaults (a scene's
// explicit <size njmax> or <size nstack> wins) and no untagged contact can
// arise. A scene that still outgrows it stops in MuJoCo's own error.
void SizeArena(mjModel* m, const ContactModel& cm);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_ARENA_H_
