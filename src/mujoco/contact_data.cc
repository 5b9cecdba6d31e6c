// Copyright contactlaws authors.

#include "contactlaws/contact_data.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "contactlaws/kinematics.h"
#include "mujoco/visible_contacts.h"
#include "mujoco/hooks.h"
#include "mujoco/narrowphase.h"

namespace contactlaws {
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

// The most tagged pairs (and geoms) for which ApplyForces tests every pair
// itself rather than taking MuJoCo's broadphase's proposals: on the cube
// tosses (one pair) MuJoCo 2.2.2's sweep-and-prune (its axis from mju_eig3,
// a sort) costs about 1,800 instructions a stage (callgrind), FarApart about
// 30 a pair.
constexpr int kOwnBroadphasePairs = 32;

// True when ApplyForces can find the contacts without MuJoCo's broadphase:
// few pairs, every pair that can collide tagged, none of them excluded by
// the scene (<exclude>) and the scene's contacts not disabled (then no
// tagged pair acts, as MuJoCo's broadphase proposes none).
bool OwnBroadphase(const ContactModel& model) {
  const mjModel* m = model.model();
  return static_cast<int>(model.pairs().size()) <= kOwnBroadphasePairs &&
         m->ngeom <= 2 * kOwnBroadphasePairs && m->nexclude == 0 &&
         !(m->opt.disableflags & (mjDSBL_CONTACT | mjDSBL_CONSTRAINT)) &&
         !HasUntaggedContacts(model);
}

bool AllFinite(const mjtNum* x, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(x[i])) return false;
  }
  return true;
}

}  // namespace

ContactData::ContactData(const ContactModel& model, mjData* d)
    : model_(model),
      m_(model.model()),
      d_(d),
      view_(*m_),
      own_broadphase_(OwnBroadphase(model)),
      episodes_(PointsPerPair(model), static_cast<int>(model.tags().size())),
      collisions_(static_cast<int>(model.pairs().size()), static_cast<int>(model.tags().size())) {
  contacts_ = MakeContactBuffer();
  const size_t points = std::min<size_t>(model.slot_count(), 4 * model.pairs().size());
  latest_.reserve(points);
  captured_.reserve(points);
  proposed_.reserve(model.pairs().size());
  is_proposed_.assign(model.pairs().size(), 0);
  previous_qvel_.assign(m_->nv, 0.0);
  current_qvel_.assign(m_->nv, 0.0);
  // MuJoCo's collision pass has nothing to do here: every pair is ours
  if (own_broadphase_) view_.opt.disableflags |= mjDSBL_CONTACT;
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
  if (has_current_ && d_->time < current_time_) Reset();
  step_start_time_ = d_->time;
  for (int i = 0; i < 3; ++i) bad_state_warnings_[i] = d_->warning[kBadStateWarnings[i]].number;
  for (const Drive& drive : model_.drives()) {
    drive.Position(d_->time, d_->mocap_pos + 3 * drive.mocap);
  }
  RecordStepStart();
  capture_armed_ = true;
  advances_unarmed_ = 0;
  has_capture_ = false;
}

void ContactData::RecordStepStart() {
  // no allocation: the buffers have nv entries from the constructor on
  std::swap(previous_qvel_, current_qvel_);
  previous_time_ = current_time_;
  has_previous_ = has_current_;
  std::copy(d_->qvel, d_->qvel + m_->nv, current_qvel_.begin());
  current_time_ = d_->time;
  has_current_ = true;
}

void ContactData::Reset() {
  latest_.clear();
  captured_.clear();
  capture_armed_ = has_capture_ = false;
  episodes_.Reset();
  collisions_.Reset();
  ledger_.Reset();
  has_previous_ = has_current_ = false;
  divergence_.reset();
}

bool ContactData::ClaimPair(int g1, int g2) {
  // the first filter call after the passive hook used the list starts the
  // next collision pass's
  if (proposals_consumed_) {
    for (const int p : proposed_) is_proposed_[p] = 0;
    proposed_.clear();
    proposals_consumed_ = false;
  }
  const int p = model_.FindPair(g1, g2);
  if (p < 0) return false;
  if (!is_proposed_[p]) {
    is_proposed_[p] = 1;
    proposals_sorted_ = proposals_sorted_ && (proposed_.empty() || proposed_.back() < p);
    proposed_.push_back(p);
  }
  return true;
}

void ContactData::NoticeUnmanagedStep() {
  // the time moves on from one evaluation to the next with no step armed
  // (RK4 moves it 3 times a step, mj_forward never)
  if (capture_armed_ || !(d_->time > latest_time_) || unmanaged_) return;
  if (++advances_unarmed_ > kUnarmedAdvancesBeforeWarning) {
    unmanaged_ = true;
    mju_warning(
        "contactlaws: this mjData is stepped without ContactData::BeforeStep/AfterStep "
        "(plain mj_step): the laws act, but keep no memory of each contact's impact "
        "velocity; step with ContactData::Step()");
  }
}

void ContactData::ApplyForces() {
  NoticeUnmanagedStep();
  latest_.clear();
  latest_time_ = d_->time;
  ApplyDrives(model_, d_);

  // the tagged pairs the broadphase proposed, in pair order (so that sums do
  // not depend on the broadphase's order)
  if (!proposals_sorted_) {
    std::sort(proposed_.begin(), proposed_.end());
    proposals_sorted_ = true;
  }
  proposals_consumed_ = true;
  const int pairs = own_broadphase_ ? static_cast<int>(model_.pairs().size())
                                    : static_cast<int>(proposed_.size());
  for (int k = 0; k < pairs; ++k) {
    const int p = own_broadphase_ ? k : proposed_[k];
    const GeomPair& pair = model_.pairs()[p];
    const int g0 = pair.geom[0];
    const int g1 = pair.geom[1];
    if (FarApart(m_, d_, g0, g1)) continue;

    // the narrowphase (MuJoCo's, or ours for box-box: narrowphase.h): dist < 0
    // is penetration, frame[0..2] the normal from geom[0] to geom[1], pos
    // midway between the surfaces
    const int count = std::min(Collide(m_, d_, g0, g1, 0, contacts_.get()), pair.slots);
    uint64_t taken = 0;
    for (int i = 0; i < count; ++i) {
      const mjContact& con = contacts_[i];
      if (!(-con.dist > 0)) continue;
      PointEvaluation e = Evaluate(p, con, &taken);

      // equal and opposite, at the same point: geom[1] pushed along +normal
      mjtNum push[3];
      for (int b = 0; b < 2; ++b) {
        mju_scl3(push, con.frame, b == 1 ? e.force : -e.force);
        AddPointForce(m_, d_, pair.body[b], con.pos, push, d_->qfrc_passive);
      }
      AddFriction(pair, con, &e);  // friction_force.cc
      latest_.push_back(e);
    }
  }

  if (capture_armed_) {
    captured_ = latest_;
    captured_time_ = latest_time_;
    capture_armed_ = false;
    has_capture_ = true;
  }
}

PointEvaluation ContactData::Evaluate(int p, const mjContact& con, uint64_t* taken) {
  const GeomPair& pair = model_.pairs()[p];
  const mjtNum* normal = con.frame;
  PointEvaluation e;
  e.pair = p;
  e.tag = pair.tag;
  e.depth = -con.dist;

  // which physical point: where it sits on the two bodies
  for (int b = 0; b < 2; ++b) {
    mjtNum offset[3];
    mju_sub3(offset, con.pos, d_->xpos + 3 * pair.body[b]);
    mju_rotVecMatT(e.local[b], offset, d_->xmat + 9 * pair.body[b]);
  }
  e.episode = episodes_.MatchOpenEpisode(p, e.local, pair.identity_tolerance, taken);

  // depth rate: approach speed of geom[0] towards geom[1] along the normal
  mjtNum v0[3], v1[3], relative[3];
  PointVelocity(pair.body[0], con.pos, v0);
  PointVelocity(pair.body[1], con.pos, v1);
  mju_sub3(relative, v0, v1);
  e.depth_rate = mju_dot3(relative, normal);

  ContactState state{e.depth, e.depth_rate, 0.0, 0.0};
  if (Law(pair.params.kind).family == LawFamily::kLinear && !pair.params.damping) {
    state.effective_mass = EffectiveMass(m_, d_, pair, con.pos, normal);
  }
  const int open = e.episode;
  e.touch = open < 0;
  if (e.touch) {
    // v0: the rate at the step before first touch, which no force has slowed
    e.at_start = !has_previous_;
    e.touch_velocity = has_previous_ ? ApproachRate(model_, d_, pair, con.pos, normal,
                                                    previous_qvel_.data(), previous_time_)
                                     : e.depth_rate;
    state.impact_velocity = std::max(e.touch_velocity, pair.params.min_impact_velocity);
    // the law at the touch itself (d = 0+, d' = v0)
    const ContactState touch{std::numeric_limits<double>::min(), e.touch_velocity,
                             state.impact_velocity, state.effective_mass};
    e.touch_power = EvaluateLaw(pair.params, touch).dissipated_power(e.touch_velocity);
    e.max_approach = e.touch_velocity;
  } else {
    // v0: the touch speed, or the largest approach rate committed since, for
    // a contact compressed faster than it touched (a pulse through touching
    // bodies: contact_memory.h, Impact::chained)
    const double committed = episodes_.MaxApproach(open);
    state.impact_velocity = std::max({episodes_.impacts()[open].impact_velocity, committed,
                                      pair.params.min_impact_velocity});
    e.max_approach = std::max(committed, e.depth_rate);
  }
  e.impact_velocity = state.impact_velocity;
  const ContactForce f = EvaluateLaw(pair.params, state);
  e.force = f.total;
  e.elastic_energy = contactlaws::ElasticEnergy(pair.params, e.depth);
  e.dissipated_power = f.dissipated_power(e.depth_rate);
  mju_copy3(e.pos, con.pos);
  mju_copy3(e.normal, normal);
  return e;
}

void ContactData::CheckDivergence() {
  if (divergence_) return;
  // the deepest contact of the step's start state, relative to its limit
  const PointEvaluation* deepest = nullptr;
  bool finite_forces = true;
  for (const PointEvaluation& e : captured_) {
    finite_forces = finite_forces && std::isfinite(e.force);
    const double limit = model_.pairs()[e.pair].depth_limit;
    if (!deepest || e.depth / limit > deepest->depth / model_.pairs()[deepest->pair].depth_limit) {
      deepest = &e;
    }
  }
  std::optional<Divergence::Kind> kind;
  std::string what;
  for (int i = 0; i < 3 && !kind; ++i) {
    const mjWarningStat& w = d_->warning[kBadStateWarnings[i]];
    if (w.number > bad_state_warnings_[i]) {
      kind = Divergence::Kind::kMujocoReset;
      what = fmt::format("MuJoCo found NaN, infinity or a value beyond {:g} in {} (dof {}) and "
                         "reset the state",
                         mjMAXVAL, i == 0 ? "qpos" : i == 1 ? "qvel" : "qacc", w.lastinfo);
    }
  }
  if (!kind && has_capture_ && d_->time < captured_time_) {
    kind = Divergence::Kind::kMujocoReset;
    what = "the time went back during the step (MuJoCo reset the state)";
  }
  if (!kind && (!AllFinite(d_->qpos, m_->nq) || !AllFinite(d_->qvel, m_->nv) ||
                !AllFinite(d_->qacc, m_->nv) || !finite_forces)) {
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
  divergence.time = *kind == Divergence::Kind::kMujocoReset ? step_start_time_
                    : has_capture_                          ? captured_time_
                                                            : current_time_;
  divergence.what = std::move(what);
  // a reset before the hook's capture: the capture is of the reset state
  const bool capture_before_reset = has_capture_ && captured_time_ == step_start_time_;
  if (deepest && (*kind != Divergence::Kind::kMujocoReset || capture_before_reset)) {
    divergence.pair = deepest->pair;
    divergence.depth = deepest->depth;
    divergence.depth_rate = deepest->depth_rate;
  }
}

void ContactData::AfterStep() {
  capture_armed_ = false;
  AppendVisibleContacts(*this, d_, &visible_overflow_);
  CheckDivergence();
  const bool commit = has_capture_ && !divergence_;
  has_capture_ = false;
  if (!commit) return;

  // the energy of the step, the episodes of its start state
  ledger_.Commit(captured_time_, captured_);
  episodes_.Commit(captured_time_, captured_);

  // the separation speed is the one the bodies leave with: their rate at
  // this first state out of contact (the step's start), at the point and
  // normal last in contact
  episodes_.CloseVanished([this](int pair, const double pos[3], const double normal[3],
                                 double last_rate) {
    return has_current_ ? -ApproachRate(model_, d_, model_.pairs()[pair], pos, normal,
                                        current_qvel_.data(), current_time_)
                        : -last_rate;
  });
  collisions_.Commit(captured_time_, captured_, episodes_);
}

TagReading ContactData::Reading(int tag) const {
  TagReading reading;
  for (const PointEvaluation& e : latest_) {
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
  for (const PointEvaluation& e : latest_) energy += e.elastic_energy + e.friction_energy;
  return energy;
}

double ContactData::DissipatedEnergy() const { return ledger_.Dissipated(latest_time_, latest_); }

}  // namespace contactlaws
