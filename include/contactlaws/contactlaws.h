// Copyright contactlaws authors.
//
// Everything a program needs to use the contact laws with MuJoCo 2.2.

#ifndef CONTACTLAWS_CONTACTLAWS_H_
#define CONTACTLAWS_CONTACTLAWS_H_

#include "contactlaws/advance.h"
#include "contactlaws/auto_timestep.h"
#include "contactlaws/contact_data.h"
#include "contactlaws/contact_memory.h"
#include "contactlaws/contact_model.h"
#include "contactlaws/error.h"
#include "contactlaws/estimate.h"
#include "contactlaws/hertz.h"
#include "contactlaws/hysteresis.h"
#include "contactlaws/kelvin_voigt.h"
#include "contactlaws/kinematics.h"
#include "contactlaws/law.h"
#include "contactlaws/model_io.h"
#include "contactlaws/run_report.h"
#include "contactlaws/settle.h"
#include "contactlaws/simulation.h"
#include "contactlaws/summary.h"
#include "contactlaws/timestep_advice.h"
#include "contactlaws/visible_contacts.h"
#include "contactlaws/measured.h"
#include "contactlaws/score.h"
#include "contactlaws/replay.h"
#include "contactlaws/fit.h"

#endif  // CONTACTLAWS_CONTACTLAWS_H_
