// Copyright contactlaws authors.

#include "contactlaws/contact_data.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <shared_mutex>
#include <unordered_map>

#include <Eigen/Core>
#include <fmt/format.h>

#include "contactlaws/error.h"

namespace contactlaws {

namespace {

// ---------------------------------------------------------------------------
// The process-wide hooks and the mjData -> ContactData registry behind them.

int FilterHook(const mjModel* m, mjData* d, int g1, int g2);
void PassiveHook(const mjModel* m, mjData* d);

struct Registry {
  std::shared_mutex mutex;
  std::unordered_map<const mjData*, ContactData*> data;
  std::atomic<uint64_t> generation{1};  // bumped by every (un)registration
  // the callbacks found when the first ContactData came: written under the
  // mutex, read by the hooks without it (a thread stepping an mjData of its
  // own may be inside a hook while another registers)
  std::atomic<mjfConFilt> previous_filter{nullptr};
  std::atomic<mjfGeneric> previous_passive{nullptr};
};

Registry& GetRegistry() {
  static Registry* registry = new Registry;  // never destroyed: hooks may run late
  return *registry;
}

// Per-thread cache of the last lookup: the hooks run per geom pair, so the
// common case (the same mjData again) takes no lock.
struct LookupCache {
  const mjData* d = nullptr;
  ContactData* contact_data = nullptr;
  uint64_t generation = 0;
};
thread_local LookupCache lookup_cache;

ContactData* Lookup(const mjModel* m, const mjData* d) {
  Registry& registry = GetRegistry();
  const uint64_t generation = registry.generation.load(std::memory_order_acquire);
  if (lookup_cache.d != d || lookup_cache.generation != generation) {
    std::shared_lock lock(registry.mutex);
    auto found = registry.data.find(d);
    lookup_cache.d = d;
    lookup_cache.contact_data = found == registry.data.end() ? nullptr : found->second;
    lookup_cache.generation = registry.generation.load(std::memory_order_acquire);
  }
  ContactData* cd = lookup_cache.contact_data;
  return cd && cd->model().model() == m ? cd : nullptr;
}

// Gives back the callbacks found before ours, unless somebody replaced ours
// since (under registry.mutex).
void RestoreCallbacks(const Registry& registry) {
  if (mjcb_contactfilter == FilterHook) mjcb_contactfilter = registry.previous_filter.load();
  if (mjcb_passive == PassiveHook) mjcb_passive = registry.previous_passive.load();
}

void Register(mjData* d, ContactData* cd) {
  Registry& registry = GetRegistry();
  std::unique_lock lock(registry.mutex);
  if (!registry.data.emplace(d, cd).second) {
    throw Error("this mjData already has a ContactData");
  }
  if (registry.data.size() == 1) {
    registry.previous_filter.store(mjcb_contactfilter, std::memory_order_release);
    registry.previous_passive.store(mjcb_passive, std::memory_order_release);
    mjcb_contactfilter = FilterHook;
    mjcb_passive = PassiveHook;
  }
  registry.generation.fetch_add(1, std::memory_order_acq_rel);
}

void Unregister(mjData* d) {
  Registry& registry = GetRegistry();
  std::unique_lock lock(registry.mutex);
  registry.data.erase(d);
  if (registry.data.empty()) {
    // previous_* stay: a hook MuJoCo entered just before this still chains
    // to them
    RestoreCallbacks(registry);
  }
  registry.generation.fetch_add(1, std::memory_order_acq_rel);
}

// At exit, or when a shared build of the library is unloaded, the callbacks
// found before are given back even if ContactData objects were leaked.
struct RestoreAtUnload {
  ~RestoreAtUnload() {
    Registry& registry = GetRegistry();
    std::unique_lock lock(registry.mutex);
    if (!registry.data.empty()) RestoreCallbacks(registry);
  }
} restore_at_unload;

int FilterHook(const mjModel* m, mjData* d, int g1, int g2) {
  // tagged: no MuJoCo constraint, the passive hook applies the law
  if (ContactData* cd = Lookup(m, d); cd && cd->ClaimPair(g1, g2)) return 1;
  mjfConFilt previous = GetRegistry().previous_filter.load(std::memory_order_acquire);
  return previous ? previous(m, d, g1, g2) : DefaultContactFilter(m, g1, g2);
}

void PassiveHook(const mjModel* m, mjData* d) {
  if (mjfGeneric previous = GetRegistry().previous_passive.load(std::memory_order_acquire)) {
    previous(m, d);
  }
  if (ContactData* cd = Lookup(m, d)) cd->ApplyForces();
}

// ---------------------------------------------------------------------------
// Geometry helpers.

// Bounding-sphere test of MuJoCo's broadphase (margin 0): true if g1 and g2
// cannot touch.
bool FarApart(const mjModel* m, const mjData* d, int g1, int g2) {
  const mjtNum r1 = m->geom_rbound[g1];
  const mjtNum r2 = m->geom_rbound[g2];
  auto plane_distance = [&](int plane, int other) {
    const mjtNum* mat = d->geom_xmat + 9 * plane;
    const mjtNum* p = d->geom_xpos + 3 * plane;
    const mjtNum* q = d->geom_xpos + 3 * other;
    return (q[0] - p[0]) * mat[2] + (q[1] - p[1]) * mat[5] + (q[2] - p[2]) * mat[8];
  };
  if (r1 > 0 && r2 > 0) {
    mjtNum dif[3];
    mju_sub3(dif, d->geom_xpos + 3 * g1, d->geom_xpos + 3 * g2);
    return mju_dot3(dif, dif) > (r1 + r2) * (r1 + r2);
  }
  if (m->geom_type[g1] == mjGEOM_PLANE && r2 > 0) return plane_distance(g1, g2) > r2;
  if (m->geom_type[g2] == mjGEOM_PLANE && r1 > 0) return plane_distance(g2, g1) > r1;
  return false;
}

}  // namespace

void AddPointForce(const mjModel* m, const mjData* d, int body, const mjtNum point[3],
                   const mjtNum force[3], mjtNum* qfrc) {
  // the body's nearest ancestor (itself included) with dofs: its last dof
  int b = body;
  while (b > 0 && m->body_dofnum[b] == 0) b = m->body_parentid[b];
  if (b <= 0) return;  // welded to the world (mocap bodies too): no dofs
  // qfrc_j += f . (lin_j + ang_j x r) = f . lin_j + ang_j . (r x f), with
  // cdof_j = (ang_j, lin_j) at the subtree com of the body's root
  mjtNum r[3], moment[3];
  mju_sub3(r, point, d->subtree_com + 3 * m->body_rootid[body]);
  mju_cross(moment, r, force);
  for (int j = m->body_dofadr[b] + m->body_dofnum[b] - 1; j >= 0; j = m->dof_parentid[j]) {
    const mjtNum* cdof = d->cdof + 6 * j;
    qfrc[j] += mju_dot3(cdof, moment) + mju_dot3(cdof + 3, force);
  }
}

// ---------------------------------------------------------------------------

ContactData::ContactData(const ContactModel& model, mjData* d)
    : model_(model), m_(model.model()), d_(d) {
  contacts_.resize(mjMAXCONPAIR);
  const size_t points = std::min<size_t>(model.slot_count(), 4 * model.pairs().size());
  latest_.reserve(points);
  captured_.reserve(points);
  slot_impact_.assign(model.slot_count(), -1);
  proposed_.reserve(model.pairs().size());
  is_proposed_.assign(model.pairs().size(), 0);
  tag_count_.assign(model.tags().size(), 0);
  previous_qvel_.assign(m_->nv, 0.0);
  current_qvel_.assign(m_->nv, 0.0);
  Register(d, this);
}

ContactData::~ContactData() { Unregister(d_); }

void ContactData::Step() {
  BeforeStep();
  mj_step(m_, d_);
  AfterStep();
}

namespace {

// The warnings of mj_checkPos, mj_checkVel and mj_checkAcc, each of which
// resets the data when it fires.
constexpr int kBadStateWarnings[3] = {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC};

bool AllFinite(const mjtNum* x, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(x[i])) return false;
  }
  return true;
}

}  // namespace

void ContactData::BeforeStep() {
  // the time went back: mj_resetData (or a keyframe) since the last step
  if (has_current_ && d_->time < current_time_) Reset();
  for (int i = 0; i < 3; ++i) bad_state_warnings_[i] = d_->warning[kBadStateWarnings[i]].number;
  for (const Drive& drive : model_.drives()) {
    drive.Position(d_->time, d_->mocap_pos + 3 * drive.mocap);
  }
  // the velocities at this step's start and the one before (no allocation:
  // the buffers have nv entries from the constructor on)
  std::swap(previous_qvel_, current_qvel_);
  previous_time_ = current_time_;
  has_previous_ = has_current_;
  std::copy(d_->qvel, d_->qvel + m_->nv, current_qvel_.begin());
  current_time_ = d_->time;
  has_current_ = true;
  capture_armed_ = true;
  advances_unarmed_ = 0;
  has_capture_ = false;
}

void ContactData::Reset() {
  latest_.clear();
  captured_.clear();
  capture_armed_ = has_capture_ = false;
  std::fill(slot_impact_.begin(), slot_impact_.end(), -1);
  std::fill(tag_count_.begin(), tag_count_.end(), 0);
  open_.clear();
  impacts_.clear();
  tracks_.clear();
  commits_ = 0;
  has_previous_ = has_current_ = false;
  has_committed_ = false;
  committed_time_ = committed_power_ = dissipated_ = 0;
  divergence_.reset();
}

void ContactData::PointVelocity(int body, const mjtNum point[3], mjtNum vel[3]) const {
  if (const Drive* drive = model_.FindDrive(body)) {
    drive->Velocity(d_->time, vel);
    return;
  }
  if (m_->body_weldid[body] == 0) {
    mju_zero3(vel);
    return;
  }
  // cvel: (angular, linear) velocity at the subtree com of the body's root
  const mjtNum* cvel = d_->cvel + 6 * body;
  mjtNum offset[3], turn[3];
  mju_sub3(offset, point, d_->subtree_com + 3 * m_->body_rootid[body]);
  mju_cross(turn, cvel, offset);
  mju_add3(vel, cvel + 3, turn);
}

void ContactData::NormalJacobian(const GeomPair& pair, const mjtNum point[3],
                                 const mjtNum normal[3], mjtNum* jn) {
  using RowJacobian = Eigen::Matrix<mjtNum, 3, Eigen::Dynamic, Eigen::RowMajor>;
  const int nv = m_->nv;
  const int mark = d_->pstack;
  Eigen::Map<RowJacobian> jac0(mj_stackAlloc(d_, 3 * nv), 3, nv);
  Eigen::Map<RowJacobian> jac1(mj_stackAlloc(d_, 3 * nv), 3, nv);
  mj_jac(m_, d_, jac0.data(), nullptr, point, pair.body[0]);
  mj_jac(m_, d_, jac1.data(), nullptr, point, pair.body[1]);
  Eigen::Map<Eigen::VectorX<mjtNum>>(jn, nv).noalias() =
      (jac1 - jac0).transpose() * Eigen::Map<const Eigen::Vector3<mjtNum>>(normal);
  d_->pstack = mark;
}

double ContactData::EffectiveMass(const GeomPair& pair, const mjtNum point[3],
                                  const mjtNum normal[3]) {
  // 1 / (n^T J M^-1 J^T n), J the relative Jacobian at point
  const int nv = m_->nv;
  const int mark = d_->pstack;
  Eigen::Map<Eigen::VectorX<mjtNum>> jn(mj_stackAlloc(d_, nv), nv);
  Eigen::Map<Eigen::VectorX<mjtNum>> x(mj_stackAlloc(d_, nv), nv);
  NormalJacobian(pair, point, normal, jn.data());
  mj_solveM(m_, d_, x.data(), jn.data(), 1);
  const double inverse_mass = jn.dot(x);
  d_->pstack = mark;
  return inverse_mass > 0 ? 1.0 / inverse_mass : std::numeric_limits<double>::infinity();
}

double ContactData::ApproachRate(const GeomPair& pair, const mjtNum point[3],
                                 const mjtNum normal[3], const mjtNum* qvel, double time) {
  // (v0 - v1) . n = -(n^T (J1 - J0)) qvel for the dofs; driven bodies through
  // their prescribed velocity at time
  const int nv = m_->nv;
  const int mark = d_->pstack;
  mjtNum* jn = mj_stackAlloc(d_, nv);
  NormalJacobian(pair, point, normal, jn);
  double rate = -mju_dot(jn, qvel, nv);
  d_->pstack = mark;
  mjtNum drive_velocity[3];
  if (const Drive* drive = model_.FindDrive(pair.body[0])) {
    drive->Velocity(time, drive_velocity);
    rate += mju_dot3(drive_velocity, normal);
  }
  if (const Drive* drive = model_.FindDrive(pair.body[1])) {
    drive->Velocity(time, drive_velocity);
    rate -= mju_dot3(drive_velocity, normal);
  }
  return rate;
}

void ContactData::ApplyDrives() {
  // translate each driven body (and its geoms) to its pose at d->time: exact at
  // every RK4 stage, where mocap_pos still holds the step's start
  for (const Drive& drive : model_.drives()) {
    mjtNum pos[3], delta[3];
    drive.Position(d_->time, pos);
    mju_sub3(delta, pos, d_->xpos + 3 * drive.body);
    mju_addTo3(d_->xpos + 3 * drive.body, delta);
    mju_addTo3(d_->xipos + 3 * drive.body, delta);
    const int first = m_->body_geomadr[drive.body];
    for (int g = first; g < first + m_->body_geomnum[drive.body]; ++g) {
      mju_addTo3(d_->geom_xpos + 3 * g, delta);
    }
  }
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

void ContactData::ApplyForces() {
  // stepped without BeforeStep: the time moves on from one evaluation to the
  // next with no step armed (RK4 moves it 3 times a step, mj_forward never)
  if (!capture_armed_ && d_->time > latest_time_ && !unmanaged_) {
    if (++advances_unarmed_ > kUnarmedAdvancesBeforeWarning) {
      unmanaged_ = true;
      mju_warning(
          "contactlaws: this mjData is stepped without ContactData::BeforeStep/AfterStep "
          "(plain mj_step): the laws act, but keep no memory of each contact's impact "
          "velocity; step with ContactData::Step()");
    }
  }
  latest_.clear();
  latest_time_ = d_->time;
  ApplyDrives();

  // the tagged pairs the broadphase proposed, in pair order (so that sums do
  // not depend on the broadphase's order)
  if (!proposals_sorted_) {
    std::sort(proposed_.begin(), proposed_.end());
    proposals_sorted_ = true;
  }
  proposals_consumed_ = true;
  const std::vector<GeomPair>& pairs = model_.pairs();
  for (const int p : proposed_) {
    const GeomPair& pair = pairs[p];
    const int g0 = pair.geom[0];
    const int g1 = pair.geom[1];
    if (FarApart(m_, d_, g0, g1)) continue;

    // MuJoCo's narrowphase: dist < 0 is penetration, frame[0..2] the normal
    // from geom[0] to geom[1], pos midway between the surfaces
    mjfCollision collide = mjCOLLISIONFUNC[m_->geom_type[g0]][m_->geom_type[g1]];
    const int count = std::min(collide(m_, d_, contacts_.data(), g0, g1, 0), pair.slots);

    for (int i = 0; i < count; ++i) {
      const mjContact& con = contacts_[i];
      const double depth = -con.dist;
      if (!(depth > 0)) continue;
      const mjtNum* normal = con.frame;

      // depth rate: approach speed of geom[0] towards geom[1] along the normal
      mjtNum v0[3], v1[3], relative[3];
      PointVelocity(pair.body[0], con.pos, v0);
      PointVelocity(pair.body[1], con.pos, v1);
      mju_sub3(relative, v0, v1);

      Evaluation e;
      e.pair = p;
      e.slot = pair.first_slot + i;
      e.depth = depth;
      e.depth_rate = mju_dot3(relative, normal);
      const int open = slot_impact_[e.slot];
      ContactState state{e.depth, e.depth_rate, 0.0, 0.0};
      const bool new_point = open < 0;
      if (pair.params.kind == LawKind::kKelvinVoigt && !pair.params.damping) {
        state.effective_mass = EffectiveMass(pair, con.pos, normal);
      }
      if (new_point) {
        e.touch_velocity = has_previous_
                               ? ApproachRate(pair, con.pos, normal, previous_qvel_.data(),
                                              previous_time_)
                               : e.depth_rate;
        state.impact_velocity = std::max(e.touch_velocity, pair.params.min_impact_velocity);
        // the law at the touch itself (d = 0+, d' = v0)
        const ContactState touch{std::numeric_limits<double>::min(), e.touch_velocity,
                                 state.impact_velocity, state.effective_mass};
        e.touch_power = EvaluateLaw(pair.params, touch).dissipated_power(e.touch_velocity);
      } else {
        state.impact_velocity =
            std::max(impacts_[open].impact_velocity, pair.params.min_impact_velocity);
      }
      e.impact_velocity = state.impact_velocity;
      const ContactForce f = EvaluateLaw(pair.params, state);
      e.force = f.total;
      e.elastic_energy = contactlaws::ElasticEnergy(pair.params, depth);
      e.dissipated_power = f.dissipated_power(e.depth_rate);

      // equal and opposite, at the same point: geom[1] pushed along +normal
      mjtNum push[3];
      for (int b = 0; b < 2; ++b) {
        mju_scl3(push, normal, b == 1 ? f.total : -f.total);
        AddPointForce(m_, d_, pair.body[b], con.pos, push, d_->qfrc_passive);
      }
      mju_copy3(e.pos, con.pos);
      mju_copy3(e.normal, normal);
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

double ContactData::Power(const std::vector<Evaluation>& evaluations) const {
  double power = 0;
  for (const Evaluation& e : evaluations) power += e.dissipated_power;
  return power;
}

void ContactData::CheckDivergence() {
  if (divergence_) return;
  // the deepest contact of the step's start state, relative to its limit
  const Evaluation* deepest = nullptr;
  bool finite_forces = true;
  for (const Evaluation& e : captured_) {
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
  divergence.time = has_capture_ ? captured_time_ : current_time_;
  divergence.what = std::move(what);
  if (deepest) {
    divergence.pair = deepest->pair;
    divergence.depth = deepest->depth;
    divergence.depth_rate = deepest->depth_rate;
  }
}

void ContactData::AfterStep() {
  capture_armed_ = false;
  CheckDivergence();
  if (!has_capture_ || divergence_) {
    has_capture_ = false;
    return;
  }
  has_capture_ = false;
  const double t = captured_time_;
  ++commits_;

  // energy dissipated since the last commit (trapezoid)
  const double power = Power(captured_);
  const double previous_time = committed_time_;
  if (has_committed_) dissipated_ += 0.5 * (power + committed_power_) * (t - previous_time);

  // open new episodes, advance the open ones
  for (const Evaluation& e : captured_) {
    int& index = slot_impact_[e.slot];
    if (index < 0) {
      Impact impact;
      impact.pair = e.pair;
      impact.tag = model_.pairs()[e.pair].tag;
      impact.index = ++tag_count_[impact.tag];
      impact.impact_velocity = e.touch_velocity;
      // the depth was reached at the mean of the touch and current rates
      const double mean_rate = 0.5 * (e.depth_rate + e.touch_velocity);
      impact.time_contact = mean_rate > 0 ? t - e.depth / mean_rate : t;
      // a new point's power acted from its touch, where a law whose force
      // jumps at d = 0+ (Kelvin-Voigt) already dissipates: its trapezoid
      // spans [touch, t] with the touch's power, not [previous commit, t]
      // from zero
      if (has_committed_) {
        const double touch = std::clamp(impact.time_contact, previous_time, t);
        dissipated_ += 0.5 * (e.touch_power + e.dissipated_power) * (t - touch) -
                       0.5 * e.dissipated_power * (t - previous_time);
      }
      index = static_cast<int>(impacts_.size());
      impacts_.push_back(impact);
      tracks_.push_back(Track{e.slot});
      open_.push_back(index);
    }
    Impact& impact = impacts_[index];
    Track& track = tracks_[index];
    impact.max_depth = std::max(impact.max_depth, e.depth);
    impact.max_force = std::max(impact.max_force, e.force);
    track.last_commit = commits_;
    track.last_time = t;
    track.last_depth = e.depth;
    track.last_rate = e.depth_rate;
    mju_copy3(track.last_pos, e.pos);
    mju_copy3(track.last_normal, e.normal);
  }

  has_committed_ = true;
  committed_time_ = t;
  committed_power_ = power;

  // close the episodes whose point is out of contact
  for (size_t k = 0; k < open_.size();) {
    const int index = open_[k];
    Track& track = tracks_[index];
    if (track.last_commit == commits_) {
      ++k;
      continue;
    }
    Impact& impact = impacts_[index];
    impact.open = false;
    // the separation speed is the one the bodies leave with: their rate at
    // this first state out of contact (the step's start), at the point and
    // normal last in contact
    impact.separation_velocity =
        has_current_ ? -ApproachRate(model_.pairs()[impact.pair], track.last_pos,
                                     track.last_normal, current_qvel_.data(), current_time_)
                     : -track.last_rate;
    const double mean_speed = 0.5 * (-track.last_rate + impact.separation_velocity);
    impact.time_separation =
        mean_speed > 0 ? track.last_time + track.last_depth / mean_speed : track.last_time;
    slot_impact_[track.slot] = -1;
    open_[k] = open_.back();
    open_.pop_back();
  }
}

TagReading ContactData::Reading(int tag) const {
  TagReading reading;
  for (const Evaluation& e : latest_) {
    if (model_.pairs()[e.pair].tag != tag) continue;
    if (e.depth > reading.depth) {
      reading.depth = e.depth;
      reading.depth_rate = e.depth_rate;
    }
    reading.force += e.force;
  }
  return reading;
}

double ContactData::ElasticEnergy() const {
  double energy = 0;
  for (const Evaluation& e : latest_) energy += e.elastic_energy;
  return energy;
}

double ContactData::DissipatedEnergy() const {
  double energy = dissipated_;
  if (has_committed_ && latest_time_ > committed_time_) {
    energy += 0.5 * (Power(latest_) + committed_power_) * (latest_time_ - committed_time_);
  }
  return energy;
}

}  // namespace contactlaws
