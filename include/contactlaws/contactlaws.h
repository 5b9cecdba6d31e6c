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
#include "contactlaws/hertz.h"
#include "contactlaws/hysteresis.h"
#include "contactlaws/kelvin_voigt.h"
#include "contactlaws/law.h"
// a scene: its model, its tags, its data and runs
#include "contactlaws/advance.h"
#include "contactlaws/auto_timestep.h"
#include "contactlaws/contact_data.h"
#include "contactlaws/contact_model.h"
#include "contactlaws/error.h"
#include "contactlaws/impact.h"
#include "contactlaws/model_io.h"
#include "contactlaws/point_evaluation.h"
#include "contactlaws/simulation.h"
// identification
#include "contactlaws/fit.h"
#include "contactlaws/measured.h"
#include "contactlaws/readable.h"
#include "contactlaws/replay.h"
#include "contactlaws/rest.h"
#include "contactlaws/score.h"
#include "contactlaws/statistics.h"

#endif  // CONTACTLAWS_CONTACTLAWS_H_
