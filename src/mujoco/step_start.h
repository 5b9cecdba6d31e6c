// Copyright contactlaws authors.
//
// StepStartVelocities: qvel at the start of the current step and of the one
// before (ContactData::BeforeStep records them): the rates just before a
// contact begins and just after it ends, which no contact force has touched.
// A touch reads its impact velocity from the step before; a separation its
// speed from the current step's start.

#ifndef CONTACTLAWS_MUJOCO_STEP_START_H_
#define CONTACTLAWS_MUJOCO_STEP_START_H_

#include <algorithm>
#include <vector>

#include <mujoco/mujoco.h>

namespace contactlaws::internal {

class StepStartVelocities {
 public:
  explicit StepStartVelocities(int nv) : current_(nv, 0.0), previous_(nv, 0.0) {}

  // d's qvel and time at a step's start; the current record becomes the
  // previous one. Allocates nothing (the buffers have nv entries).
  void Record(const mjData* d) {
    std::swap(previous_, current_);
    previous_time_ = current_time_;
    std::copy(d->qvel, d->qvel + current_.size(), current_.begin());
    current_time_ = d->time;
    recorded_ = std::min(recorded_ + 1, 2);
  }

  // Forgets both records (their times stay, for the time going back).
  void Forget() { recorded_ = 0; }

  bool has_current() const { return recorded_ >= 1; }
  bool has_previous() const { return recorded_ >= 2; }
  const mjtNum* current() const { return current_.data(); }
  const mjtNum* previous() const { return previous_.data(); }
  double current_time() const { return current_time_; }   // s
  double previous_time() const { return previous_time_; } // s

 private:
  std::vector<mjtNum> current_;
  std::vector<mjtNum> previous_;
  double current_time_ = 0;
  double previous_time_ = 0;
  int recorded_ = 0;  // steps recorded since Forget, counted up to 2
};

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_MUJOCO_STEP_START_H_
