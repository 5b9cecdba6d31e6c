// Copyright contactlaws authors.
//
// The program's mjData arena, sized to the scene before its runs share the
// model. MuJoCo 2.2.2 sizes the data's arena by its defaults (njmax = 500
// constraint rows: 3 MB zeroed by mj_makeData; nstack from a heuristic on
// njmax), whatever the scene. A scene whose every collidable pair is tagged
// makes no contact constraint, so its rows are bounded by its equality
// constraints, friction losses and limits. What it buys: a run's
// mj_makeData, once per run of a sweep (docs/performance.md).

#ifndef CONTACTLAWS_APP_ARENA_H_
#define CONTACTLAWS_APP_ARENA_H_

#include <string>

#include <mujoco/mujoco.h>

#include "contactlaws/contact_model.h"

namespace contactlaws::app {

// Sizes m's arena to the scene before mj_makeData: njmax to the rows it can
// need, nstack by MuJoCo's own heuristic for that njmax plus what the
// passive hook takes. Only when both are MuJoCo's defaults (a scene's
// explicit <size njmax> or <size nstack> wins) and no untagged contact can
// arise. A scene that still outgrows it stops in MuJoCo's own error.
void SizeArena(mjModel* m, const ContactModel& cm);

// The scene at path (LoadModelFile) with its arena sized to its tags as the
// overrides leave them, before any run shares it. A scene whose tags are
// refused is left as MuJoCo made it: the run that reads them refuses it.
// With CONTACTLAWS_ARENA=mujoco in the environment, MuJoCo's sizes stay.
UniqueModel LoadSizedModel(const std::string& path, const Overrides& overrides);

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_ARENA_H_
