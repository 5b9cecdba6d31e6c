// Copyright contactlaws authors.
//
// The process-wide hooks (mjcb_contactfilter, mjcb_passive) and the
// mjData -> ContactData registry behind them. The first registered
// ContactData installs the hooks; the last one gives back the callbacks found
// before. See contact_data.h for what the hooks do. With them, what MuJoCo's
// own filter lets collide.

#ifndef CONTACTLAWS_MUJOCO_HOOKS_H_
#define CONTACTLAWS_MUJOCO_HOOKS_H_

#include <mujoco/mujoco.h>

namespace contactlaws {

class ContactData;
class ContactModel;

// MuJoCo 2.2.2's own contact filter for a geom pair (not exported by the
// library): 1 discards. Installing mjcb_contactfilter replaces it for every
// pair, so untagged pairs go through this copy of the rule.
int DefaultContactFilter(const mjModel* m, int g1, int g2);

// Throws Error when d already has a ContactData.
void RegisterContactData(mjData* d, ContactData* contact_data);
void UnregisterContactData(mjData* d);

// True when MuJoCo may make a contact constraint: an explicit <contact><pair>,
// or two geoms that MuJoCo's own filter (DefaultContactFilter) lets collide
// and no tag of cm claims.
bool HasUntaggedContacts(const ContactModel& cm);

}  // namespace contactlaws

#endif  // CONTACTLAWS_MUJOCO_HOOKS_H_
