// Copyright contactlaws authors.
//
// The process-wide hooks (mjcb_contactfilter, mjcb_passive) and the
// mjData -> ContactData registry behind them. The first registered
// ContactData installs the hooks; the last one gives back the callbacks found
// before. See contact_data.h for what the hooks do.

#ifndef CONTACTLAWS_MUJOCO_HOOKS_H_
#define CONTACTLAWS_MUJOCO_HOOKS_H_

#include <mujoco/mujoco.h>

namespace contactlaws {

class ContactData;

// Throws Error when d already has a ContactData.
void RegisterContactData(mjData* d, ContactData* contact_data);
void UnregisterContactData(mjData* d);

}  // namespace contactlaws

#endif  // CONTACTLAWS_MUJOCO_HOOKS_H_
