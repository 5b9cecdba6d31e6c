// Copyright contactlaws authors.
//
// The protocol between ContactData and MuJoCo's hooks within a step:
//   ProposedPairs  the tagged pairs the contact filter claimed in the latest
//                  collision pass, which the passive hook evaluates;
//   StepCapture    the passive hook's first evaluation after BeforeStep (the
//                  step's start state), which AfterStep commits, and the
//                  notice of an mjData stepped without BeforeStep.
// Each keeps its protocol in one enum.

#ifndef CONTACTLAWS_MUJOCO_HOOK_SESSION_H_
#define CONTACTLAWS_MUJOCO_HOOK_SESSION_H_

#include <algorithm>
#include <cstdint>
#include <vector>

#include "contactlaws/contact_model.h"
#include "contactlaws/impact.h"

namespace contactlaws::internal {

class ProposedPairs {
 public:
  explicit ProposedPairs(const ContactModel& model);

  // The filter's claim of pair p (-1: an untagged pair). The first claim
  // after an evaluation used the list starts the next collision pass's.
  // O(1); no allocation.
  void Claim(int p) {
    if (state_ == State::kUsed) StartPass();
    if (p < 0 || is_proposed_[p]) return;
    is_proposed_[p] = 1;
    if (!pairs_.empty() && pairs_.back() > p) state_ = State::kUnsorted;
    pairs_.push_back(p);
  }

  // The pairs an evaluation covers, in pair order (so that sums do not depend
  // on the broadphase's order): the claimed ones (the same again when a pass
  // was skipped, e.g. mj_forwardSkip past positions), or every pair when
  // ContactData is its own broadphase.
  const std::vector<int>& Use() {
    if (state_ == State::kUnsorted) std::sort(pairs_.begin(), pairs_.end());
    state_ = State::kUsed;
    return own_broadphase_ ? every_pair_ : pairs_;
  }

  // The claimed pairs, as the latest claims left them.
  const std::vector<int>& claimed() const { return pairs_; }

  // True when ContactData tests every tagged pair itself (a cheap bounding
  // test each) and MuJoCo's collision pass is off: few pairs, every pair that
  // can collide tagged, none excluded (<exclude>), contacts not disabled.
  bool own_broadphase() const { return own_broadphase_; }

 private:
  enum class State {
    kSorted,    // claims of this pass, in pair order
    kUnsorted,  // claims of this pass, out of order
    kUsed,      // an evaluation took the list (sorted); the next claim restarts it
  };
  void StartPass();

  bool own_broadphase_;
  std::vector<int> every_pair_;  // 0 .. pairs - 1, when own_broadphase_
  std::vector<int> pairs_;
  std::vector<uint8_t> is_proposed_;  // per pair
  State state_ = State::kUsed;
};

class StepCapture {
 public:
  explicit StepCapture(size_t points) { points_.reserve(points); }

  // BeforeStep: the next evaluation is the step's start state.
  void Arm() {
    phase_ = Phase::kArmed;
    if (unarmed_advances_ <= kUnarmedAdvancesBeforeWarning) unarmed_advances_ = 0;
  }
  // After each evaluation (points at time t): kept when armed.
  void Offer(const std::vector<PointEvaluation>& points, double t) {
    if (phase_ != Phase::kArmed) return;
    points_ = points;
    time_ = t;
    phase_ = Phase::kHeld;
  }
  // AfterStep: no evaluation of this step is captured any more.
  void Disarm() {
    if (phase_ == Phase::kArmed) phase_ = Phase::kIdle;
  }
  // AfterStep, once committed (or refused): the capture is spent.
  void Release() { phase_ = Phase::kIdle; }
  // Forgets the captured points.
  void Reset() {
    points_.clear();
    phase_ = Phase::kIdle;
  }

  // An evaluation at time t after the latest at latest_time: warns once
  // (mju_warning) when the time moves on unarmed for several evaluations,
  // i.e. the data is stepped by plain mj_step (RK4 moves it 3 times a step,
  // mj_forward never).
  void NoticeEvaluation(double t, double latest_time);

  // The step's start state was captured this step.
  bool held() const { return phase_ == Phase::kHeld; }
  // The next evaluation is the step's start state.
  bool armed() const { return phase_ == Phase::kArmed; }
  // The latest captured points and their time (kept after Release, until
  // the next capture or Reset).
  const std::vector<PointEvaluation>& points() const { return points_; }
  double time() const { return time_; }  // s

 private:
  enum class Phase {
    kIdle,   // no step armed, or its capture spent
    kArmed,  // BeforeStep ran: the next evaluation is captured
    kHeld,   // the step's start evaluation is captured, for AfterStep
  };
  // Evaluations at a later time, unarmed, before the warning; past it the
  // count stays above (the warning is given once).
  static constexpr int kUnarmedAdvancesBeforeWarning = 8;

  std::vector<PointEvaluation> points_;
  double time_ = 0;
  Phase phase_ = Phase::kIdle;
  int unarmed_advances_ = 0;
};

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_MUJOCO_HOOK_SESSION_H_
