// Copyright contactlaws authors.

#include "mujoco/hook_session.h"

#include <numeric>

#include <mujoco/mujoco.h>

#include "mujoco/hooks.h"

namespace contactlaws::internal {
namespace {

// The most tagged pairs (and geoms) for which ContactData tests every pair
// itself rather than taking MuJoCo's broadphase's proposals: on the cube
// tosses (one pair) MuJoCo 2.2.2's sweep-and-prune (its axis from mju_eig3,
// a sort) costs about 1,800 instructions a stage (callgrind), FarApart about
// 30 a pair.
constexpr int kOwnBroadphasePairs = 32;

// True when the passive hook can find the contacts without MuJoCo's
// broadphase: few pairs, every pair that can collide tagged, none of them
// excluded by the scene (<exclude>) and the scene's contacts not disabled
// (then no tagged pair acts, as MuJoCo's broadphase proposes none).
bool OwnBroadphase(const ContactModel& model) {
  const mjModel* m = model.model();
  return static_cast<int>(model.pairs().size()) <= kOwnBroadphasePairs &&
         m->ngeom <= 2 * kOwnBroadphasePairs && m->nexclude == 0 &&
         !(m->opt.disableflags & (mjDSBL_CONTACT | mjDSBL_CONSTRAINT)) &&
         !HasUntaggedContacts(model);
}

}  // namespace

ProposedPairs::ProposedPairs(const ContactModel& model) : own_broadphase_(OwnBroadphase(model)) {
  const size_t pairs = model.pairs().size();
  if (own_broadphase_) {
    every_pair_.resize(pairs);
    std::iota(every_pair_.begin(), every_pair_.end(), 0);
  }
  pairs_.reserve(pairs);
  is_proposed_.assign(pairs, 0);
}

void ProposedPairs::StartPass() {
  for (const int p : pairs_) is_proposed_[p] = 0;
  pairs_.clear();
  state_ = State::kSorted;
}

void StepCapture::NoticeEvaluation(double t, double latest_time) {
  if (phase_ == Phase::kArmed || !(t > latest_time) ||
      unarmed_advances_ > kUnarmedAdvancesBeforeWarning) {
    return;
  }
  if (++unarmed_advances_ > kUnarmedAdvancesBeforeWarning) {
    mju_warning(
        "contactlaws: this mjData is stepped without ContactData::BeforeStep/AfterStep "
        "(plain mj_step): the laws act, but keep no memory of each contact's impact "
        "velocity; step with ContactData::Step()");
  }
}

}  // namespace contactlaws::internal
