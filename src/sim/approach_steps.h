// Copyright contactlaws authors.
//
// The steps the pairs apart allow the auto timestep (auto_timestep.h): how
// fast each pair near enough to matter closes its gap, and the
// step that closes a fraction of it, or the fine step cut at the predicted
// touch; an untagged pair asks for the scene's own step while MuJoCo's
// contact can reach it.

#ifndef CONTACTLAWS_SIM_APPROACH_STEPS_H_
#define CONTACTLAWS_SIM_APPROACH_STEPS_H_

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "contactlaws/contact_data.h"
#include "sim/contact_steps.h"

namespace contactlaws {

namespace internal {
class ReachSweep;  // mujoco/reach_sweep.h
}  // namespace internal

// The time in which a gap g (m, > 0) closes at speed v and acceleration a
// (both closing when > 0); infinite when it never does.
double TimeToClose(double g, double v, double a);

class ApproachSteps {
 public:
  // contacts must outlive this object; a step may close at most gap_fraction
  // of a pair's gap.
  ApproachSteps(const ContactData& contacts, double gap_fraction);
  ~ApproachSteps();
  ApproachSteps(ApproachSteps&&) noexcept;

  // Limits *bound by the steps the pairs apart allow from the current state
  // of d (its kinematics computed), among those that could close within
  // reach_bound (s). in_contact: per pair, nonzero for the pairs in contact,
  // which are skipped. *fine is set when a tagged pair is near.
  void Step(const mjData* d, double reach_bound, const std::vector<uint8_t>& in_contact,
            const PairSteps& pair_steps, StepBound* bound, bool* fine);

  // Whether a pair that MuJoCo's own contact handles exists.
  bool has_untagged() const { return has_untagged_; }

 private:
  // How two geoms close, from the current state: the gap between their
  // bounding spheres (or a plane and a sphere), m, and its closing speed (the
  // centres' relative velocity along the line between them plus what spin
  // can add, nothing for a sphere) and acceleration (gravity, drives'
  // top_acceleration).
  struct Closing {
    double gap = 0;
    double speed = 0;
    double accel = 0;
  };
  // False when a geom has no bounding sphere (a plane against a plane or a
  // height field, ...): then no gap is known.
  bool Closes(const std::array<int, 2>& geom, const std::array<int, 2>& body,
              double top_acceleration, Closing* c) const;
  // Limits *bound by the step tagged pair p (out of contact) allows: the
  // time to close a fraction of its gap, or the fine step when it is near
  // (then *fine is set), landed just before and just past its predicted
  // touch.
  void PairStep(int p, const PairSteps& pair_steps, StepBound* bound, bool* fine) const;
  // The step the untagged pair of geoms g0, g1 allows (MuJoCo's contact
  // starts at margin, m): the scene's own step while it is within margin or
  // could close gap_fraction of its gap beyond it within that step;
  // otherwise the time to close that fraction.
  double UntaggedStep(int g0, int g1, double margin) const;
  // reach_ for a step of at most bound (s): how far each geom's surface may
  // move towards another's within it, over gap_fraction, twice over, beyond
  // its margin; a pair whose reaches do not overlap cannot shorten the step.
  void SetReach(double bound);

  const ContactData& contacts_;
  double gap_fraction_;
  std::vector<double> top_acceleration_;  // of each pair's driven bodies, m/s^2
  bool has_untagged_ = false;
  double scene_step_ = 0;                 // s, the model's opt.timestep as it was given
  std::unique_ptr<internal::ReachSweep> sweep_;     // the pairs near enough to matter
  std::vector<double> reach_;             // per geom, m (SetReach)
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_APPROACH_STEPS_H_
