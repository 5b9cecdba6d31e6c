// Copyright contactlaws authors.

#include "mujoco/step_committer.h"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "mujoco/kinematics.h"

namespace contactlaws::internal {
namespace {

// The warnings of mj_checkPos, mj_checkVel and mj_checkAcc, each of which
// resets the data when it fires.
constexpr int kBadStateWarnings[3] = {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC};

// The most points each pair can have at once.
std::vector<int> PointsPerPair(const ContactModel& model) {
  std::vector<int> points;
  for (const GeomPair& pair : model.pairs()) points.push_back(pair.slots);
  return points;
}

bool AllFinite(const mjtNum* x, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(x[i])) return false;
  }
  return true;
}

}  // namespace

StepCommitter::StepCommitter(const ContactModel& model)
    : model_(model),
      episodes_(PointsPerPair(model), static_cast<int>(model.tags().size())),
      impacts_(static_cast<int>(model.pairs().size()), static_cast<int>(model.tags().size())) {}

void StepCommitter::BeforeStep(const mjData* d) {
  for (int i = 0; i < 3; ++i) bad_state_warnings_[i] = d->warning[kBadStateWarnings[i]].number;
}

void StepCommitter::Reset() {
  episodes_.Reset();
  impacts_.Reset();
  ledger_.Reset();
  divergence_.reset();
}

void StepCommitter::StartWith(double t, const std::vector<PointEvaluation>& points) {
  std::vector<PointEvaluation> touches(points);
  for (PointEvaluation& e : touches) {
    e.episode = -1;
    e.touch = e.at_start = true;
  }
  episodes_.Commit(t, touches);
  impacts_.Commit(t, touches, episodes_);
}

void StepCommitter::CheckDivergence(const mjData* d, const StepCapture& capture,
                                    const StepStartVelocities& start) {
  if (divergence_) return;
  const mjModel* m = model_.model();
  // the deepest contact of the step's start state, relative to its limit
  const PointEvaluation* deepest = nullptr;
  bool finite_forces = true;
  for (const PointEvaluation& e : capture.points()) {
    finite_forces = finite_forces && std::isfinite(e.force);
    const double limit = model_.pairs()[e.pair].depth_limit;
    if (!deepest || e.depth / limit > deepest->depth / model_.pairs()[deepest->pair].depth_limit) {
      deepest = &e;
    }
  }
  std::optional<Divergence::Kind> kind;
  std::string what;
  for (int i = 0; i < 3 && !kind; ++i) {
    const mjWarningStat& w = d->warning[kBadStateWarnings[i]];
    if (w.number > bad_state_warnings_[i]) {
      kind = Divergence::Kind::kMujocoReset;
      what = fmt::format("MuJoCo found NaN, infinity or a value beyond {:g} in {} (dof {}) and "
                         "reset the state",
                         mjMAXVAL, i == 0 ? "qpos" : i == 1 ? "qvel" : "qacc", w.lastinfo);
    }
  }
  if (!kind && capture.held() && d->time < capture.time()) {
    kind = Divergence::Kind::kMujocoReset;
    what = "the time went back during the step (MuJoCo reset the state)";
  }
  if (!kind && (!AllFinite(d->qpos, m->nq) || !AllFinite(d->qvel, m->nv) ||
                !AllFinite(d->qacc, m->nv) || !finite_forces)) {
    kind = Divergence::Kind::kNonFinite;
    what = "NaN or infinity in the state or a contact force";
  }
  if (!kind && deepest) {
    const GeomPair& pair = model_.pairs()[deepest->pair];
    if (deepest->depth > pair.depth_limit) {
      kind = Divergence::Kind::kTooDeep;
      what = fmt::format("depth {:.4g} m beyond {:.4g} m ({} of the smaller geom's size)",
                         deepest->depth, pair.depth_limit, kDivergenceDepthFraction);
    }
  }
  if (!kind) return;
  Divergence& divergence = divergence_.emplace();
  divergence.kind = *kind;
  // a reset state reads time 0: the step that found it started before
  const double step_start = start.current_time();
  divergence.time = *kind == Divergence::Kind::kMujocoReset ? step_start
                    : capture.held()                        ? capture.time()
                                                            : step_start;
  divergence.what = std::move(what);
  // a reset before the hook's capture: the capture is of the reset state
  const bool capture_before_reset = capture.held() && capture.time() == step_start;
  if (deepest && (*kind != Divergence::Kind::kMujocoReset || capture_before_reset)) {
    divergence.pair = deepest->pair;
    divergence.depth = deepest->depth;
    divergence.depth_rate = deepest->depth_rate;
  }
}

double StepCommitter::SeparationSpeed(mjData* d, int pair, const double pos[3],
                                     const double normal[3], double last_rate,
                                     const StepStartVelocities& start) const {
  return start.has_current() ? -ApproachRate(model_, d, model_.pairs()[pair], pos, normal,
                                             start.current(), start.current_time())
                             : -last_rate;
}

void StepCommitter::CommitInner(mjData* d, ContactStepper* inner,
                                const StepStartVelocities& start) {
  inner_episode_.assign(inner->point_count(), -1);
  for (int k = 0; k < inner->sample_count(); ++k) {
    InnerSample& sample = inner->samples()[k];
    for (size_t j = 0; j < sample.points.size(); ++j) {
      PointEvaluation& e = sample.points[j];
      if (k > 0 && !e.touch) e.episode = inner_episode_[sample.ids[j]];
    }
    const int before = static_cast<int>(episodes_.episodes().size());
    ledger_.Commit(sample.time, sample.points);
    episodes_.Commit(sample.time, sample.points);
    int opened = 0;
    for (size_t j = 0; j < sample.points.size(); ++j) {
      const PointEvaluation& e = sample.points[j];
      inner_episode_[sample.ids[j]] = e.episode < 0 ? before + opened++ : e.episode;
    }
    episodes_.CloseVanished([&](int pair, const double pos[3], const double normal[3],
                                double last_rate) {
      // within the step: the rows' rate; at its start, separated in the
      // step before's last sub-step: that step's rows' rate at its end
      const int id = k == 0 ? -1 : inner->FindPoint(pair, pos);
      if (id >= 0) return -inner->Rate(k, id);
      double rate = 0;
      if (k == 0 && inner->EndRate(pair, pos, &rate)) return -rate;
      return SeparationSpeed(d, pair, pos, normal, last_rate, start);
    });
    impacts_.Commit(sample.time, sample.points, episodes_);
  }
  ledger_.Book(inner->dissipation_correction());
  for (int id = 0; id < inner->point_count(); ++id) {
    double energy = 0, half_step = 0;
    if (inner_episode_[id] >= 0 && inner->LastSubStep(id, &energy, &half_step)) {
      ledger_.Defer(inner_episode_[id], energy, half_step);
    }
  }
}

void StepCommitter::AfterStep(mjData* d, const std::vector<PointEvaluation>& latest,
                              const StepCapture& capture, const StepStartVelocities& start,
                              int integrator, ContactStepper* inner) {
  if (list_visible_points_) AppendVisiblePoints(model_, latest, d, &visible_overflow_);
  CheckDivergence(d, capture, start);
  if (!capture.held() || divergence_) return;
  if (inner && inner->sample_count() > 0) return CommitInner(d, inner, start);

  // the energy of the step, the episodes of its start state
  const std::vector<PointEvaluation>& points = capture.points();
  // MuJoCo's Euler and implicit integrators hold the laws' forces (explicit,
  // in qfrc_passive) through the step; RK4's stages follow them
  const DissipationLedger::Booking booking = integrator == mjINT_RK4
                                                 ? DissipationLedger::Booking::kTrapezoid
                                                 : DissipationLedger::Booking::kHeldForce;
  ledger_.Commit(capture.time(), points, booking);
  episodes_.Commit(capture.time(), points);

  // the separation speed is the one the bodies leave with: their rate at
  // this first state out of contact (the step's start), at the point and
  // normal last in contact
  episodes_.CloseVanished([&](int pair, const double pos[3], const double normal[3],
                              double last_rate) {
    return SeparationSpeed(d, pair, pos, normal, last_rate, start);
  });
  impacts_.Commit(capture.time(), points, episodes_);
}

}  // namespace contactlaws::internal
