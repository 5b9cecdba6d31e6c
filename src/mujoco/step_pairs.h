// Copyright contactlaws authors.
//
// StepPairs: the tagged pairs a step with its contacts integrated inside it
// (contact_stepper.h) must evaluate: those whose geoms can come within reach
// of each other during the step. MuJoCo's collision pass proposes only the
// pairs whose bounding boxes overlap now (grown by geom_margin): a pair that
// closes its gap within the step would be missed, and the next step would
// start deep inside it (64 balls at 2 ms diverged within 0.04 s). Growing
// geom_margin would reach the narrowphase of the untagged pairs too
// (MuJoCo's constraint activates within the margin), so the tagged pairs are
// found here instead: each geom's bounding sphere grown by its reach over the
// step, swept (ReachSweep), and kept when MuJoCo 2.2.2's broadphase proposes
// the pair once near (ProposedWhenNear).

#ifndef CONTACTLAWS_MUJOCO_STEP_PAIRS_H_
#define CONTACTLAWS_MUJOCO_STEP_PAIRS_H_

#include <cstdint>
#include <memory>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/contact_model.h"

namespace contactlaws::internal {

class ReachSweep;  // mujoco/reach_sweep.h

// How far a step's reach looks, in multiples of how far the step's start
// speeds and gravity carry a geom (or close a pair) within it: what pushes a
// body from elsewhere during the step (another contact, an actuator) is not
// in them. The narrowphase margin of a pair (ContactStepper::Reach) and the
// geoms' reaches here both take it.
constexpr double kStepReachFactor = 2.0;

// True when MuJoCo 2.2.2's collision pass (engine_collision_driver.c:
// mj_collision, mj_broadphase) proposes geoms g0 and g1 to the contact filter
// once their bodies' boxes overlap: contacts enabled and not restricted to
// <pair>; the world's geoms, and a static body's planes and height fields,
// meet every body; other bodies only when both have a geom with contype or
// conaffinity, and two single-geom bodies only when those match. (Excluded
// bodies and geoms of one weld body are never tagged pairs.)
bool ProposedWhenNear(const mjModel* m, int g0, int g1);

class StepPairs {
 public:
  // model must outlive this object.
  explicit StepPairs(const ContactModel& model);
  ~StepPairs();

  // The tagged pairs, in pair order, whose geoms' bounding spheres, each
  // grown by its reach over a step of h s at d's state (cvel current),
  // overlap, and that MuJoCo proposes once near. A geom's reach is
  // kStepReachFactor times (|v| + |w| rbound) h + |g| h^2 / 2 at its centre's
  // velocity v and its body's spin w: two geoms' reaches add up to at least
  // the pair's (ContactStepper::Reach), so that no pair the narrowphase
  // margin would take is left out. No allocation once warm.
  const std::vector<int>& Find(const mjData* d, double h);
  // The pairs the latest Find found.
  const std::vector<int>& pairs() const { return pairs_; }

 private:
  const ContactModel& model_;
  std::unique_ptr<ReachSweep> sweep_;
  std::vector<uint8_t> proposed_;  // per pair: ProposedWhenNear
  std::vector<double> reach_;      // per geom, m
  std::vector<int> pairs_;
};

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_MUJOCO_STEP_PAIRS_H_
