// Copyright contactlaws authors.
//
// ContactData: the laws acting on one mjData.
//
// While a ContactData exists, MuJoCo's global hooks are ours (installed by the
// first ContactData, the callbacks found before restored when the last one is
// destroyed):
//   mjcb_contactfilter  discards the tagged geom pairs of this data's model
//                       (MuJoCo makes no constraint for them), records them
//                       as proposed by the broadphase, and applies MuJoCo's
//                       own rule, or the callback found before, to every
//                       other pair;
//   mjcb_passive        runs MuJoCo's narrowphase on each tagged pair the
//                       broadphase proposed (so the cost grows with the pairs
//                       near each other, not with all tagged pairs), evaluates
//                       the pair's law at each contact point and adds the force
//                       to qfrc_passive (after the callback found before).
// An mjData with no ContactData is left entirely to MuJoCo.
//
// The hooks are pure functions of the state they are given (RK4 calls the
// passive hook four times a step): the per-contact memory (impact velocity v0,
// episode, energy) is committed once per accepted step, from the evaluation
// at the step's start state, by AfterStep(). A user's loop is therefore
//
//   contactlaws::ContactData contacts(contact_model, d);
//   while (...) contacts.Step();      // BeforeStep(); mj_step(m, d); AfterStep();
//
// mj_resetData (the time going back) is noticed by the next BeforeStep, which
// then forgets the per-contact memory; after any other jump of the state, call
// Reset(). After each step, divergence() says whether the run can go on.
//
// One model, many data: the model is only read (mj_step takes a const
// mjModel*), so data of one model step on as many threads. MuJoCo reads the
// timestep and the integrator from m->opt, so the options a data is stepped
// with are its own (options()): Step() gives mj_step a view of the model, a
// copy of its header whose arrays are the model's, never written, and whose
// opt is this data's. A step of a length of its own, Step(timestep), sets the
// data's options, never the model's. The model must not change while data
// use it.
//
// Inside, ContactData is a facade over objects with one job each
// (src/mujoco/): the hook session (the pairs the broadphase proposed, the
// capture of the step's start evaluation), the point evaluator (the laws and
// friction at each contact point), the step committer (episodes, impacts,
// energy, divergence, visible contacts) and the step-start velocities.

#ifndef CONTACTLAWS_CONTACT_DATA_H_
#define CONTACTLAWS_CONTACT_DATA_H_

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/contact_model.h"
#include "contactlaws/impact.h"

namespace contactlaws {

namespace internal {
// The facade's objects (src/mujoco/).
class PointEvaluator;
class ProposedPairs;
class StepCapture;
class StepCommitter;
class ContactStepper;
class StepStartVelocities;
// MuJoCo's hooks (src/mujoco/hooks.cc): the only callers of ClaimPair and
// ApplyForces.
struct HookCalls;
}  // namespace internal

// What did not fit in d->contact (m->nconmax entries in MuJoCo 2.2.2) over
// the calls that shared this record (AppendVisibleContacts). The first point
// dropped raises one warning (mju_warning), the rest are only counted.
struct VisibleContactsOverflow {
  long dropped = 0;
};

// Contacts integrated inside the step (docs/timestep.md, "Contact steps"):
// at each step's start the points in contact or within reach of the step
// are integrated over it in sub-steps of their own, the configuration
// frozen, and act on the bodies as their mean force. Off by default: each
// point's law then acts at the step's states, as MuJoCo steps it.
inline constexpr int kContactStepsAuto = -1;
struct ContactStepsOptions {
  // 0: off; N > 0: N sub-steps in every step with points; kContactStepsAuto:
  // per step, from its points' elastic durations and dampers (below).
  int substeps = 0;
  // With kContactStepsAuto: RK4 sub-steps per elastic contact duration. A
  // sub-step ends at a touch, so nothing but RK4's truncation is left: at 20
  // (80 for Kelvin-Voigt, whose clamp F >= 0 is a kink inside the contact)
  // the paper's ball at 2 ms rebounds within 2e-4 of the exact 1-D solution
  // for flores 0.9, hunt-crossley 0.5, lankarani-nikravesh 0.8, hertz and
  // kelvin-voigt 0.3, and at 10 (40) within 1.1e-3 (docs/timestep.md,
  // "Sub-steps per contact").
  double per_contact_hertz = 20;
  double per_contact_linear = 80;
  // The most sub-steps in one step (beyond: one warning, and this many).
  int max_substeps = 100000;
  bool enabled() const { return substeps != 0; }
};

// The sub-steps a user writes: "auto" (kContactStepsAuto) or a whole number
// in [1, 1e6]; nullopt for anything else, which callers refuse with
// kContactStepsRequirement.
std::optional<int> ParseContactSteps(std::string_view text);
inline constexpr const char* kContactStepsRequirement =
    "must be auto or a whole number of sub-steps in [1, 1e6]";

// A run with contact steps is warned when a body with points in or near
// contact turns more than this (rad) within one step: its lever arms, and
// so A and the points' rates, move by about as much relative to the frozen
// configuration the step is integrated in (a 2 cm die spinning at 21 rad/s:
// 0.042 rad a 2 ms step, its first corner rebound 0.654 against 0.769 at
// fine steps; docs/timestep.md, "Contact steps").
inline constexpr double kFrozenTurnWarning = 0.01;

// The latest evaluation of one tag: its deepest contact point, and the sum of
// the forces of all its points.
struct TagReading {
  double depth = 0;       // m, 0 when out of contact
  double depth_rate = 0;  // m/s, 0 when out of contact
  double force = 0;       // N, normal
  // N, world frame: the friction force on the tag's geom1 (GeomPair::named[0])
  double friction[3] = {0, 0, 0};
};

class ContactData {
 public:
  // model must describe d's mjModel and outlive this object.
  ContactData(const ContactModel& model, mjData* d);
  ~ContactData();

  ContactData(const ContactData&) = delete;
  ContactData& operator=(const ContactData&) = delete;

  // One accepted step: BeforeStep(); mj_step(model_view(), d); AfterStep().
  // An mjData stepped with plain mj_step gets one MuJoCo warning
  // (mju_warning) after a few steps: its contacts then have no memory.
  void Step();
  // One step of the given length, s (> 0): it becomes this data's timestep.
  void Step(double timestep);

  // The options this data is stepped with: the model's when this object was
  // made, then this data's own (its timestep, integrator, ...).
  const mjOption& options() const { return view_.opt; }
  mjOption& options() { return view_.opt; }

  // The model as this data is stepped: the model's header with options(),
  // its arrays the model's. Give it, not the model, to MuJoCo's functions on
  // this data for its options to hold (mj_forward reads the timestep too:
  // MuJoCo's soft constraints are never stiffer than two timesteps).
  const mjModel* model_view() const { return &view_; }

  // Moves driven (mocap) bodies to their prescribed pose at d->time and arms
  // the capture of the step's first hook evaluation.
  void BeforeStep();

  // Commits the per-contact memory from the evaluation captured at the step's
  // start state, and lists the tagged contact points of the step's last
  // evaluation in d->contact, outside the solver, for MuJoCo's visualisation
  // (AppendVisibleContacts, visible_contacts.h).
  void AfterStep();

  // Contacts integrated inside each step from now on (ContactStepsOptions),
  // or not (substeps 0). Under Euler, implicit and RK4.
  void SetContactSteps(const ContactStepsOptions& options);
  const ContactStepsOptions& contact_steps() const;
  // The sub-steps of the last step's contacts (0: none, or off).
  int last_substeps() const;
  // With contact steps: the largest angle (rad) a body with points in or
  // near contact turned within one step at its spin at the step's start,
  // and that step's time (s): the frozen configuration's measure
  // (docs/timestep.md, "Contact steps").
  double contact_steps_worst_turn() const;
  double contact_steps_worst_turn_time() const;
  // The first step (its time, s) whose turn was beyond kFrozenTurnWarning,
  // or -1: where the frozen configuration first costs accuracy (a hammer's
  // first impact, before its worst turn).
  double contact_steps_first_far_turn_time() const;

  // Forgets every episode, the energy ledger and any divergence. BeforeStep
  // calls it when the time has gone back (mj_resetData).
  void Reset();

  // After Reset: opens an episode for each of points at the data's time, as
  // a step's commit of that state would, with its friction_state as its
  // committed friction (a settled start's contacts carrying their load:
  // Simulation with SimulationOptions::settle). Each point is taken as a
  // contact there at the start (PointEvaluation::at_start).
  void StartWith(const std::vector<PointEvaluation>& points);

  // From now on, steps (and mj_forward with model_view()) keep up to date
  // only the state, what MuJoCo computes from it for the dynamics, and the
  // contacts' memory: MuJoCo's cameras and lights are not placed
  // (model_view() has none: mj_camlight), and AfterStep does not list the
  // tagged contact points in d->contact. For rollouts that read the bodies'
  // motion alone (replay, fit), where these cost 3% of the step.
  void KeepMotionOnly();

  // Set by the AfterStep that found the state diverged; the state is then
  // not to be trusted (MuJoCo may even have reset it).
  const std::optional<Divergence>& divergence() const;

  const ContactModel& model() const { return model_; }
  const mjData* data() const { return d_; }
  mjData* data() { return d_; }

  // Every impact so far, one per pair from its first point touching to
  // its last point leaving (ImpactLog), in order of first touch.
  const std::vector<Episode>& impacts() const;

  // Every contact episode of every contact point so far, in order of first
  // touch: a point is followed by where it sits on the two bodies.
  const std::vector<Episode>& point_episodes() const;

  // One contact point as the hook last saw it.
  using Evaluation = PointEvaluation;

  // The contact points of the latest hook evaluation (depth > 0).
  const std::vector<Evaluation>& latest() const;

  // The tagged pairs the last collision pass proposed (what ApplyForces
  // evaluates), in pair order.
  const std::vector<int>& proposed_pairs() const;

  // The latest hook evaluation (call mj_forward first for the current state).
  TagReading Reading(int tag) const;
  // J, latest evaluation: the laws' springs and the stick springs of friction
  double ElasticEnergy() const;
  // J, the energy of the law's spring at point e's depth (computed when
  // asked: the hooks' four evaluations a step do not need it)
  double LawEnergy(const PointEvaluation& e) const;
  // J, integrated (trapezoid) over committed steps, up to the latest evaluation
  double DissipatedEnergy() const;

  // World-frame velocity of a point fixed to body (driven bodies: their
  // prescribed motion). Needs cvel (mj_forward, or inside the hooks).
  void PointVelocity(int body, const mjtNum point[3], mjtNum vel[3]) const;

 private:
  friend struct internal::HookCalls;

  // Called by the contact filter hook for each pair the broadphase proposes:
  // true, and recorded for ApplyForces, when the pair is tagged. O(1); no
  // allocation.
  bool ClaimPair(int g1, int g2);

  // Called by the passive hook: adds the laws' forces to d->qfrc_passive for
  // the tagged pairs the last collision pass proposed (the same pairs again
  // when the pass was skipped, e.g. mj_forwardSkip past positions).
  void ApplyForces();

  const ContactModel& model_;
  mjData* d_;
  mjModel view_;  // the model's header with this data's options: model_view()
  std::unique_ptr<internal::ProposedPairs> proposals_;
  std::unique_ptr<internal::StepCapture> capture_;
  std::unique_ptr<internal::StepStartVelocities> step_start_;
  std::unique_ptr<internal::PointEvaluator> evaluator_;
  std::unique_ptr<internal::StepCommitter> committer_;
  std::unique_ptr<internal::ContactStepper> stepper_;
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_CONTACT_DATA_H_
