// Copyright contactlaws authors.
//
// ContactData: the facade that sequences its objects (contact_data.h) over a
// step: BeforeStep arms them, the hooks claim pairs and evaluate, AfterStep
// commits.

#include "contactlaws/contact_data.h"

#include <algorithm>
#include <cmath>

#include "mujoco/contact_stepper.h"
#include "mujoco/kinematics.h"
#include "mujoco/hook_session.h"
#include "mujoco/hooks.h"
#include "mujoco/point_evaluator.h"
#include "mujoco/step_committer.h"
#include "mujoco/step_start.h"
#include "scene/number.h"

namespace contactlaws {

using internal::ContactStepper;
using internal::PointEvaluator;
using internal::ProposedPairs;
using internal::StepCapture;
using internal::StepCommitter;
using internal::StepStartVelocities;

ContactData::ContactData(const ContactModel& model, mjData* d)
    : model_(model),
      d_(d),
      view_(*model.model()),
      proposals_(std::make_unique<ProposedPairs>(model)),
      capture_(std::make_unique<StepCapture>(
          std::min<size_t>(model.slot_count(), 4 * model.pairs().size()))),
      step_start_(std::make_unique<StepStartVelocities>(model.model()->nv)),
      evaluator_(std::make_unique<PointEvaluator>(model)),
      committer_(std::make_unique<StepCommitter>(model)),
      stepper_(std::make_unique<ContactStepper>(model)) {
  // MuJoCo's collision pass has nothing to do here: every pair is ours
  if (proposals_->own_broadphase()) view_.opt.disableflags |= mjDSBL_CONTACT;
  RegisterContactData(d, this);
}

ContactData::~ContactData() { UnregisterContactData(d_); }

void ContactData::Step() {
  BeforeStep();
  mj_step(&view_, d_);
  AfterStep();
}

void ContactData::Step(double timestep) {
  view_.opt.timestep = timestep;
  Step();
}

void ContactData::BeforeStep() {
  // the time went back: mj_resetData (or a keyframe) since the last step
  if (step_start_->has_current() && d_->time < step_start_->current_time()) Reset();
  committer_->BeforeStep(d_);
  for (const Drive& drive : model_.drives()) {
    drive.Position(d_->time, d_->mocap_pos + 3 * drive.mocap);
  }
  step_start_->Record(d_);
  capture_->Arm();
}

void ContactData::Reset() {
  evaluator_->Reset();
  capture_->Reset();
  committer_->Reset();
  step_start_->Forget();
  stepper_->Forget();
}

void ContactData::StartWith(const std::vector<PointEvaluation>& points) {
  committer_->StartWith(d_->time, points);
}

void ContactData::KeepMotionOnly() {
  view_.ncam = 0;
  view_.nlight = 0;
  committer_->ListVisiblePoints(false);
}

bool ContactData::ClaimPair(int g1, int g2) {
  const int p = model_.FindPair(g1, g2);
  proposals_->Claim(p);
  return p >= 0;
}

void ContactData::ApplyForces() {
  capture_->NoticeEvaluation(d_->time, evaluator_->latest_time());
  ApplyDrives(model_, d_);
  // contacts integrated inside the step: at its start, and its later
  // evaluations (RK4's stages) take the same mean force; any other
  // evaluation (mj_forward) is the laws at its state
  const bool start = capture_->armed();
  ContactStepper* inner = stepper_->enabled() && (start || capture_->held()) ? stepper_.get()
                                                                            : nullptr;
  // the pairs: MuJoCo's broadphase's (or every pair, ours), or, with the
  // contacts integrated inside the step, those that can touch within it
  // (MuJoCo's proposes only those near now)
  const std::vector<int>& proposed = proposals_->Use();
  const std::vector<int>& pairs = inner && !proposals_->own_broadphase()
                                      ? inner->Pairs(d_, view_.opt.timestep, start)
                                      : proposed;
  evaluator_->Evaluate(d_, pairs, committer_->episodes(), *step_start_, inner,
                       view_.opt.timestep);
  if (inner && start) {
    inner->Integrate(&view_, d_, evaluator_->latest());
  } else if (inner) {
    inner->ApplyForce(&view_, d_);
  }
  capture_->Offer(evaluator_->latest(), evaluator_->latest_time());
}

void ContactData::AfterStep() {
  capture_->Disarm();
  const bool inner = stepper_->enabled() && capture_->held() && d_->time > capture_->time();
  if (inner) stepper_->CorrectPositions(&view_, d_);
  committer_->AfterStep(d_, evaluator_->latest(), *capture_, *step_start_, view_.opt.integrator,
                        inner ? stepper_.get() : nullptr);
  stepper_->Committed();
  stepper_->Spend();
  capture_->Release();
}

void ContactData::SetContactSteps(const ContactStepsOptions& options) {
  stepper_->set_options(options);
}

const ContactStepsOptions& ContactData::contact_steps() const { return stepper_->options(); }

int ContactData::last_substeps() const { return stepper_->substeps(); }

double ContactData::contact_steps_worst_turn() const { return stepper_->worst_turn(); }

double ContactData::contact_steps_worst_turn_time() const { return stepper_->worst_turn_time(); }

double ContactData::contact_steps_first_far_turn_time() const {
  return stepper_->first_far_turn_time();
}

const std::optional<Divergence>& ContactData::divergence() const {
  return committer_->divergence();
}

const std::vector<Episode>& ContactData::impacts() const {
  return committer_->impacts().impacts();
}

const std::vector<Episode>& ContactData::point_episodes() const {
  return committer_->episodes().episodes();
}

const std::vector<ContactData::Evaluation>& ContactData::latest() const {
  return evaluator_->latest();
}

const std::vector<int>& ContactData::proposed_pairs() const { return proposals_->claimed(); }

void ContactData::PointVelocity(int body, const mjtNum point[3], mjtNum vel[3]) const {
  contactlaws::PointVelocity(model_, d_, body, point, vel);
}

TagReading ContactData::Reading(int tag) const {
  TagReading reading;
  for (const PointEvaluation& e : latest()) {
    if (e.tag != tag) continue;
    if (e.depth > reading.depth) {
      reading.depth = e.depth;
      reading.depth_rate = e.depth_rate;
    }
    reading.force += e.force;
    // e.friction acts on the pair's geom[1]; geom1 of the tag gets its opposite
    // when it is geom[0]
    const GeomPair& pair = model_.pairs()[e.pair];
    const double sign = pair.named[0] == pair.geom[1] ? 1.0 : -1.0;
    for (int i = 0; i < 3; ++i) reading.friction[i] += sign * e.friction[i];
  }
  return reading;
}

double ContactData::ElasticEnergy() const {
  double energy = 0;
  for (const PointEvaluation& e : latest()) energy += LawEnergy(e) + e.friction_energy;
  return energy;
}

double ContactData::LawEnergy(const PointEvaluation& e) const {
  return e.weight * contactlaws::ElasticEnergy(model_.pairs()[e.pair].params, e.depth);
}

double ContactData::DissipatedEnergy() const {
  return committer_->ledger().Dissipated(evaluator_->latest_time(), evaluator_->latest());
}

std::optional<int> ParseContactSteps(std::string_view text) {
  if (text == "auto") return kContactStepsAuto;
  const std::optional<double> value = ParseNumber(text);
  if (!value || !(*value >= 1) || *value != std::floor(*value) || *value > 1e6) return std::nullopt;
  return static_cast<int>(*value);
}

}  // namespace contactlaws
