// Copyright contactlaws authors.

#include "contactlaws/auto_timestep.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "contactlaws/contact_model.h"
#include "sim/estimate.h"
#include "mujoco/damper_rate.h"
#include "mujoco/kinematics.h"
#include "sim/approach_steps.h"
#include "sim/contact_steps.h"

namespace contactlaws {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The time in which a depth d (m, > 0) separating at speed v (> 0) reaches 0
// under an acceleration a that closes the pair (gravity: > 0); infinite when
// it does not.
double TimeToSeparate(double d, double v, double a) {
  if (a <= 0) return TimeToClose(d, v, -a);
  const double discriminant = v * v - 2 * a * d;
  if (discriminant < 0) return kInfinity;
  return 2 * d / (v + std::sqrt(discriminant));  // the smaller root, without cancellation
}

// The step that ends at a predicted separation goes this fraction of a fine
// step beyond it, so that it lands out of contact although the prediction
// leaves out the law's force (small near d = 0): the separation speed then
// carries gravity's slowing over 1e-3 of a fine step, not over up to a whole
// fine step (a first-order error in the rebound).
constexpr double kSeparationOvershoot = 1e-3;
// The bound on friction's dampers, in lags 1 / lambda: RK4 damps a
// mode of rate lambda monotonically up to 2.785 lags (its amplification at 2
// lags is 1/3); 2 leaves room for the law's dampers on the same bodies.
// Measured on the resting die: 3.2e-5 s (2.65 lags) stops it, 3.4e-5 s
// (2.8) keeps it spinning.
constexpr double kFrictionDamperLags = 2;
// And on the laws' dampers of a pair's several points, on the inertia at
// them: the same 2 lags, within RK4's 2.785. The translation's m / c keeps
// its one lag (a box placed on a floor settles onto its weight within it),
// so a cube, which rocks against its corners at 1.5 c / m, keeps its steps;
// a 1 x 1 x 0.1 m plate under 25 balls, rocking at ~3 c / m, was stepped
// at 3 lags and fed 0.046 J in 0.2 s.
constexpr double kNormalDamperLags = 2;

// Euler and implicit integrate a parabola with a first-order error: their
// flight step is the step of the rule before --accuracy (1e-3 s at the
// default accuracy) scaled by accuracy / kDefaultAccuracy.
constexpr double kFirstOrderFlightStep = 1e-3;

// True when the scene has dynamics of its own besides free bodies, gravity,
// the tagged pairs, drives and untagged contacts (those bound the step only
// while near: UntaggedStep): their time scales are the scene's.
bool HasOwnDynamics(const ContactModel& cm) {
  const mjModel* m = cm.model();
  if (m->nu || m->ntendon || m->neq || m->opt.density > 0 || m->opt.viscosity > 0 ||
      m->opt.wind[0] || m->opt.wind[1] || m->opt.wind[2] || mjcb_control) {
    return true;
  }
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_stiffness[j] > 0 || m->jnt_limited[j]) return true;
    // a body on a hinge or a ball joint swings under gravity: a pendulum
    if (m->jnt_type[j] == mjJNT_HINGE || m->jnt_type[j] == mjJNT_BALL) return true;
  }
  for (int v = 0; v < m->nv; ++v) {
    if (m->dof_damping[v] > 0 || m->dof_frictionloss[v] > 0) return true;
  }
  return false;
}

// Below it a body's inertia is a sphere's (rounding of a cube's): it spins
// about a fixed axis, which every integrator turns exactly.
constexpr double kSphericalInertia = 1e-9;

}  // namespace

// A single free body's principal moments are the model's (body_inertia);
// a free body with bodies welded below it has their composite inertia about
// their centre of mass, at qpos0 (a rigid set unless joints below move it,
// which are the scene's own dynamics: HasOwnDynamics), from MuJoCo's crb.
std::vector<AutoTimestep::Spinner> AutoTimestep::Spinners(const mjModel* m) {
  std::vector<AutoTimestep::Spinner> spinners;
  UniqueData d;  // for a composite body's crb, made once when one is met
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_type[j] != mjJNT_FREE) continue;
    const int b = m->jnt_bodyid[j];
    Eigen::Vector3d principal;  // ascending
    if (SingleFreeBody(m, b)) {
      principal = Eigen::Vector3d(m->body_inertia[3 * b], m->body_inertia[3 * b + 1],
                                  m->body_inertia[3 * b + 2]);
      std::sort(principal.data(), principal.data() + 3);
    } else {
      if (!d) {
        d.reset(mj_makeData(m));
        if (!d) throw Error("AutoTimestep: MuJoCo could not allocate mjData");
        mj_kinematics(m, d.get());
        mj_comPos(m, d.get());
        mj_crb(m, d.get());
      }
      // crb: the composite inertia (xx, yy, zz, xy, xz, yz first) about the
      // subtree's centre of mass, world axes
      const mjtNum* c = d->crb + 10 * b;
      Eigen::Matrix3d inertia;
      inertia << c[0], c[3], c[4], c[3], c[1], c[5], c[4], c[5], c[2];
      principal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia, Eigen::EigenvaluesOnly)
                      .eigenvalues();
    }
    if (!(principal[0] > 0)) continue;
    const double anisotropy = (principal[2] - principal[0]) / principal[0];
    if (anisotropy > kSphericalInertia) spinners.push_back({m->jnt_dofadr[j], anisotropy});
  }
  return spinners;
}

double StepsPerContact(double accuracy) {
  return kDefaultStepsPerContact * std::pow(kDefaultAccuracy / accuracy, kStepsExponent);
}

double KelvinVoigtStepsPerContact(double accuracy) {
  return kKelvinVoigtStepsAtDefault * std::sqrt(kDefaultAccuracy / accuracy);
}

AutoTimestep::AutoTimestep(const ContactData& contacts, const AutoTimestepOptions& options)
    : contacts_(contacts),
      options_(options),
      approach_(std::make_unique<ApproachSteps>(contacts, options.gap_fraction)),
      damper_rate_(std::make_unique<internal::DamperRate>()) {
  if (!(options.accuracy > 0 && options.accuracy <= kMaxAccuracy) || !(options.max_step > 0) ||
      !(options.steps_per_contact >= 0) || !(options.kelvin_voigt_steps_per_contact >= 0) ||
      !(options.gap_fraction > 0) || !(options.gap_fraction < 1) || !(options.growth >= 1)) {
    throw Error(fmt::format(
        "AutoTimestepOptions: accuracy {} must be in (0, {}], max_step {} > 0, "
        "steps_per_contact {} >= 0, gap_fraction {} in (0, 1), growth {} >= 1",
        options.accuracy, kMaxAccuracy, options.max_step, options.steps_per_contact,
        options.gap_fraction, options.growth));
  }
  if (options_.steps_per_contact == 0) options_.steps_per_contact = StepsPerContact(options.accuracy);
  if (options_.kelvin_voigt_steps_per_contact == 0) {
    options_.kelvin_voigt_steps_per_contact = KelvinVoigtStepsPerContact(options.accuracy);
  }
  flight_step_ = FlightStep();
  const ContactModel& cm = contacts.model();
  for (int p = 0; p < static_cast<int>(cm.pairs().size()); ++p) {
    effective_mass_.push_back(PairEffectiveMass(cm, p));
  }
  pair_steps_ = std::make_unique<PairSteps>(
      cm, effective_mass_,
      ContactSteps(options_.steps_per_contact, options_.kelvin_voigt_steps_per_contact));
  in_contact_.assign(cm.pairs().size(), 0);
  pair_damping_.assign(cm.pairs().size(), 0.0);
  binding_.assign(2 * cm.pairs().size(), 0);
  settled_rule_ = contacts.options().integrator == mjINT_RK4;
  spinners_ = Spinners(cm.model());
}

AutoTimestep::~AutoTimestep() = default;
AutoTimestep::AutoTimestep(AutoTimestep&&) noexcept = default;

double AutoTimestep::FlightStep() const {
  const ContactModel& cm = contacts_.model();
  double step = options_.max_step;
  // the data's options: a step of its own, or the scene's
  const mjOption& opt = contacts_.options();
  if (HasOwnDynamics(cm)) step = std::min(step, opt.timestep);
  if (opt.integrator != mjINT_RK4) {
    step = std::min(step, kFirstOrderFlightStep * options_.accuracy / kDefaultAccuracy);
  }
  return step;
}

double AutoTimestep::SpinStep(const mjData* d) const {
  double step = kInfinity;
  for (const Spinner& s : spinners_) {
    const mjtNum* w = d->qvel + s.dof + 3;
    const double rate = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * s.anisotropy;
    if (rate > 0) step = std::min(step, 2 * mjPI / (rate * options_.steps_per_contact));
  }
  return step;
}

double AutoTimestep::TangentialStep(const ContactData::Evaluation& e) const {
  const GeomPair& pair = contacts_.model().pairs()[e.pair];
  const FrictionParams& f = pair.friction;
  if (f.kind == FrictionKind::kNone) return kInfinity;
  // the stick spring (or bristles, or regularized curve) at this point's
  // stiffness and load, on the pair's mass
  const double k = e.friction_state.stiffness;
  double duration = TangentialDuration(
      f, k, TangentialDamping(f, pair.params, State(e), k, pair.friction_mass),
      pair.friction_mass, e.force);
  // the rolling and torsional springs, critically damped on the pair's
  // moment of inertia
  const double lengths[2] = {f.torsional, f.rolling};
  for (int part = 0; part < 2; ++part) {
    const double k = e.friction_state.torque_stiffness[part];
    if (lengths[part] > 0 && k > 0) {
      duration = std::min(duration, M_PI * std::sqrt(pair.friction_inertia / k));
    }
  }
  // its period 2 duration, as a contact's duration (the fixed-step rule:
  // kStepsPerContact in either)
  return pair_steps_->steps().TangentialStep(duration);
}

double AutoTimestep::FrictionLag(mjData* d, size_t first, size_t end, double pace) {
  const std::vector<ContactData::Evaluation>& points = contacts_.latest();
  const GeomPair& pair = contacts_.model().pairs()[points[first].pair];
  if (pair.friction.kind == FrictionKind::kNone) return kInfinity;
  return DampersLag(d, first, end, internal::DamperDirection::kTangential, kFrictionDamperLags,
                    pace, [&](size_t i) {
    const ContactData::Evaluation& e = points[i];
    const double k = e.friction_state.stiffness;
    const double c = TangentialDamping(pair.friction, pair.params, State(e), k, pair.friction_mass);
    return TangentialDynamics(pair.friction, k, c, pair.friction_mass, e.force).damping;
  });
}

double AutoTimestep::NormalLag(mjData* d, size_t first, size_t end, double pace) {
  return DampersLag(d, first, end, internal::DamperDirection::kNormal, kNormalDamperLags, pace,
                    [&](size_t i) { return law_damping_[i]; });
}

template <typename Damping>
double AutoTimestep::DampersLag(mjData* d, size_t first, size_t end,
                                internal::DamperDirection direction, double lags, double pace,
                                const Damping& damping) {
  const std::vector<ContactData::Evaluation>& points = contacts_.latest();
  const GeomPair& pair = contacts_.model().pairs()[points[first].pair];
  point_pos_.clear();
  point_normal_.clear();
  point_damping_.clear();
  for (size_t i = first; i < end; ++i) {
    const ContactData::Evaluation& e = points[i];
    point_pos_.insert(point_pos_.end(), e.pos, e.pos + 3);
    point_normal_.insert(point_normal_.end(), e.normal, e.normal + 3);
    point_damping_.push_back(damping(i));
  }
  const int count = static_cast<int>(end - first);
  // lags / rate >= lags / bound (rate <= bound): when that is no shorter
  // than pace, the exact lag would not shorten the step either. A pair
  // whose lag bound the last step is likely to bind this one (a resting
  // box's friction): its bound is not tried.
  uint8_t& bound_last = binding_[2 * points[first].pair + static_cast<int>(direction)];
  const mjModel* m = contacts_.model().model();
  bool bounded = false;  // Bound's rows formed at this state
  if (!bound_last) {
    // first the bound from the bodies' inertia alone, then Bound's
    const double inertia_bound = damper_rate_->InertiaBound(
        m, d, pair, count, point_pos_.data(), point_damping_.data(), direction);
    if (lags / inertia_bound >= pace) return lags / inertia_bound;
    const double bound = damper_rate_->Bound(m, d, pair, count, point_pos_.data(),
                                             point_normal_.data(), point_damping_.data(),
                                             direction);
    if (lags / bound >= pace) return lags / bound;
    bounded = true;
  }
  const double rate = bounded ? damper_rate_->RateAfterBound(m)
                              : damper_rate_->Rate(m, d, pair, count, point_pos_.data(),
                                                   point_normal_.data(),
                                                   point_damping_.data(), direction);
  const double lag = rate > 0 ? lags / rate : kInfinity;
  bound_last = lag < pace;
  return lag;
}

ContactState AutoTimestep::State(const ContactData::Evaluation& e) const {
  return PointState(e, effective_mass_[e.pair]);
}

void AutoTimestep::ContactStep(const ContactData::Evaluation& e, StepBound* bound) const {
  const double floor = contacts_.model().pairs()[e.pair].params.min_impact_velocity;
  const double tangential = TangentialStep(e);
  // a settled contact (it touched barely faster than the law's floor of v0
  // and moves no faster than it): no impact to resolve, only a spring to
  // keep stable under RK4 (the dampers' lags still bound its step)
  const double fine = pair_steps_->Fine(e.pair, e.impact_velocity);
  if (settled_rule_ && std::abs(e.depth_rate) <= floor && e.episode >= 0) {
    const double lasted = contacts_.data()->time - contacts_.point_episodes()[e.episode].time_contact;
    const bool slow_touch = e.impact_velocity <= kSettledTouchFactor * floor;
    if (slow_touch || lasted > kSettledDurations * fine * pair_steps_->PerContact(e.pair)) {
      bound->Limit(std::min(pair_steps_->Settled(e.pair), tangential));
      return;
    }
  }
  // a separation slower than the law's floor of v0 (a resting contact's
  // chatter) is left to the fine step
  if (!(-e.depth_rate > floor)) {
    bound->Limit(std::min(fine, tangential));
    return;
  }
  const GeomPair& pair = contacts_.model().pairs()[e.pair];
  const double closing = GravityClosingAcceleration(contacts_.model(), pair, e.normal);
  const double overshoot = kSeparationOvershoot * fine;
  const double separation = TimeToSeparate(e.depth, -e.depth_rate, closing) + overshoot;
  bound->Land(separation, std::min(fine, tangential));
}

double AutoTimestep::Next(mjData* d, double until) {
  const ContactModel& cm = contacts_.model();
  const mjModel* m = cm.model();
  const int npair = static_cast<int>(cm.pairs().size());
  StepBound bound{flight_step_, flight_step_};
  bool fine = false;

  // pairs in contact at the last evaluation (a pair may have several
  // points): their fine step
  int in_contact = 0;
  law_damping_.clear();
  for (const ContactData::Evaluation& e : contacts_.latest()) {
    ContactStep(e, &bound);
    fine = true;
    if (!in_contact_[e.pair]) {
      in_contact_[e.pair] = 1;
      ++in_contact;
    }
    // a weighted point's damper is its weight's share (a face patch's)
    law_damping_.push_back(e.weight * DampingCoefficient(cm.pairs()[e.pair].params, State(e)));
    pair_damping_[e.pair] += law_damping_.back();
  }
  // the laws' damping as dampers, a pair's points in parallel: a step no
  // longer than its lag m / c (a contact settling at the v0 floor is stiff:
  // DampingCoefficient)
  for (const ContactData::Evaluation& e : contacts_.latest()) {
    double& c = pair_damping_[e.pair];
    bound.Limit(DamperLag(effective_mass_[e.pair], c));
    c = 0;
  }
  // and friction's dampers, on the inertia at the points (the points come
  // pair by pair); a pair's several points also turn its bodies against the
  // laws' dampers (a box rocking on its corners)
  const size_t points = contacts_.latest().size();
  for (size_t first = 0, end = 0; first < points; first = end) {
    while (end < points && contacts_.latest()[end].pair == contacts_.latest()[first].pair) ++end;
    bound.Limit(FrictionLag(d, first, end, bound.pace));
    if (end - first > 1) bound.Limit(NormalLag(d, first, end, bound.pace));
  }

  // the other pairs: the time to close a fraction of their gap, from the
  // current state
  if (in_contact < npair || approach_->has_untagged()) {
    mj_kinematics(m, d);
    mj_comPos(m, d);
    mj_comVel(m, d);
    // the pairs that could close within the step so far, growth included
    const double reach =
        previous_ > 0 ? std::min(bound.step, options_.growth * previous_) : bound.step;
    approach_->Step(d, reach, in_contact_, *pair_steps_, &bound, &fine);
  }

  bound.Limit(SpinStep(d));

  for (const ContactData::Evaluation& e : contacts_.latest()) in_contact_[e.pair] = 0;
  if (fine) finest_step_ = std::min(finest_step_, bound.pace);
  if (previous_ > 0) bound.Limit(options_.growth * previous_);
  // the next step grows from the pace: neither a landing on a touch or a
  // separation nor a cut at `until` slows the growth after it
  previous_ = bound.pace;
  const double step = std::min(bound.step, until);
  ++steps_;
  fine_steps_ += fine;
  return step;
}

}  // namespace contactlaws
