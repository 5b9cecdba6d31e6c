// Copyright contactlaws authors.
//
// The installed API, in one include: the contact laws and friction models as
// pure kernels, a tagged scene loaded and stepped with them (alone, in your
// own loop, or with the auto timestep), and the identification of a scene's
// parameters from measured trajectories. docs/library.md lists what each
// header gives.

#ifndef CONTACTLAWS_CONTACTLAWS_H_
#define CONTACTLAWS_CONTACTLAWS_H_

// the kernels: plain numbers in, forces out
#include "contactlaws/friction.h"
#include "contactlaws/law.h"
// a scene: its model, its tags, its data and runs
#include "contactlaws/simulation.h"
#include "contactlaws/auto_timestep.h"
#include "contactlaws/contact_data.h"
#include "contactlaws/contact_model.h"
#include "contactlaws/impact.h"
// identification
#include "contactlaws/fit.h"
#include "contactlaws/replay.h"

#endif  // CONTACTLAWS_CONTACTLAWS_H_
