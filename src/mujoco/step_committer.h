// Copyright contactlaws authors.
//
// StepCommitter: what an accepted step leaves behind, once a step, from the
// evaluation captured at the step's start state (hook_session.h): the
// divergence check, the episodes of every contact point and the impacts
// of every pair (contact_memory.h), the energy ledger, and the tagged contact
// points listed in d->contact for MuJoCo's visualisation
// (visible_contacts.h). The only writer of the per-contact memory.

#ifndef CONTACTLAWS_MUJOCO_STEP_COMMITTER_H_
#define CONTACTLAWS_MUJOCO_STEP_COMMITTER_H_

#include <array>
#include <optional>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/contact_data.h"
#include "memory/contact_memory.h"
#include "contactlaws/contact_model.h"
#include "mujoco/contact_stepper.h"
#include "mujoco/hook_session.h"
#include "mujoco/step_start.h"

namespace contactlaws::internal {

class StepCommitter {
 public:
  // model must outlive this object.
  explicit StepCommitter(const ContactModel& model);

  // At a step's start: MuJoCo's bad-state warning counts, whose rise during
  // the step means mj_step found NaN/huge values and reset the data.
  void BeforeStep(const mjData* d);

  // After the step: lists latest (the step's last evaluation) in d->contact,
  // sets divergence() when the step diverged, and else commits capture (the
  // step's start, when held) into the memory. start: the velocities recorded
  // at this step's start and the one before. integrator: the one that took
  // the step (the data's options, which a run may set apart from the
  // model's), which decides how the ledger books it.
  // inner: the step's contacts integrated inside it, whose sub-samples are
  // committed in its start's stead (contact_stepper.h); or none.
  void AfterStep(mjData* d, const std::vector<PointEvaluation>& latest,
                 const StepCapture& capture, const StepStartVelocities& start, int integrator,
                 ContactStepper* inner = nullptr);

  // Forgets every episode, impact, the energy and any divergence.
  void Reset();

  // Opens an episode and an impact for each of points at time t (after
  // Reset), touches there at the start, with their friction states.
  void StartWith(double t, const std::vector<PointEvaluation>& points);

  // AfterStep lists the tagged points in d->contact (the default), or not.
  void ListVisiblePoints(bool list) { list_visible_points_ = list; }

  const EpisodeLog& episodes() const { return episodes_; }
  const ImpactLog& impacts() const { return impacts_; }
  const DissipationLedger& ledger() const { return ledger_; }
  const std::optional<Divergence>& divergence() const { return divergence_; }

 private:
  // Commits inner's sub-samples, each as a step's start: the first is the
  // step's start (its separations read from start), the others close their
  // episodes at the inner rates.
  void CommitInner(mjData* d, ContactStepper* inner, const StepStartVelocities& start);
  // -d' of the first state out of contact at pos, normal of pair: at the
  // step's start velocities (start), or last_rate's opposite without them.
  double SeparationSpeed(mjData* d, int pair, const double pos[3], const double normal[3],
                         double last_rate, const StepStartVelocities& start) const;

  // Sets divergence_ when the step diverged.
  void CheckDivergence(const mjData* d, const StepCapture& capture,
                       const StepStartVelocities& start);

  const ContactModel& model_;
  std::array<int, 3> bad_state_warnings_ = {0, 0, 0};
  std::optional<Divergence> divergence_;
  VisibleContactsOverflow visible_overflow_;
  bool list_visible_points_ = true;
  EpisodeLog episodes_;
  ImpactLog impacts_;
  DissipationLedger ledger_;
  std::vector<int> inner_episode_;  // CommitInner: per inner point, its episode
};

// Appends each of points (evaluated on model's pairs) to d->contact, as
// AppendVisibleContacts (visible_contacts.h) does for a ContactData's
// latest(). Returns how many were appended.
int AppendVisiblePoints(const ContactModel& model, const std::vector<PointEvaluation>& points,
                        mjData* d, VisibleContactsOverflow* overflow);

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_MUJOCO_STEP_COMMITTER_H_
