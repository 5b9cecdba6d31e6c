// Copyright contactlaws authors.

#include "contactlaws/auto_timestep.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "contactlaws/error.h"
#include "sim/estimate.h"
#include "mujoco/damper_rate.h"
#include "mujoco/hooks.h"
#include "sim/reach_sweep.h"

namespace contactlaws {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The time in which a gap g (m, > 0) closes at speed v and acceleration a
// (both closing when > 0); infinite when it never does.
double TimeToClose(double g, double v, double a) {
  if (a > 0) return (-v + std::sqrt(v * v + 2 * a * g)) / a;
  if (v > 0) return g / v;
  return kInfinity;
}

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
// Likewise the step that reaches a predicted touch ends this fraction of a
// fine step past it, in contact, whatever the rounding of the prediction.
constexpr double kTouchOvershoot = 1e-3;

// Rule 5's bound on friction's dampers, in lags 1 / lambda: RK4 damps a
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
  }
  for (int v = 0; v < m->nv; ++v) {
    if (m->dof_damping[v] > 0 || m->dof_frictionloss[v] > 0) return true;
  }
  return false;
}

// The top acceleration of the driven bodies among body, m/s^2 (A w^2 each).
double DriveAcceleration(const ContactModel& cm, const std::array<int, 2>& body) {
  double accel = 0;
  for (int b : body) {
    if (const Drive* drive = cm.FindDrive(b)) {
      accel += std::abs(drive->amplitude) * drive->omega * drive->omega;
    }
  }
  return accel;
}

}  // namespace

double StepsPerContact(double accuracy) {
  return kDefaultStepsPerContact * std::pow(kDefaultAccuracy / accuracy, kStepsExponent);
}

double KelvinVoigtStepsPerContact(double accuracy) {
  return kKelvinVoigtStepsAtDefault * std::sqrt(kDefaultAccuracy / accuracy);
}

AutoTimestep::AutoTimestep(const ContactData& contacts, const AutoTimestepOptions& options)
    : contacts_(contacts),
      options_(options),
      sweep_(std::make_unique<internal::ReachSweep>(contacts.model().model())),
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
    const GeomPair& pair = cm.pairs()[p];
    const double mass = PairEffectiveMass(cm, p);
    effective_mass_.push_back(mass);
    // t_c is proportional to v^((1 - n) / (1 + n)) (Hertz family; KV: v^0)
    const double n = Law(pair.params.kind).family == LawFamily::kLinear ? 1.0 : pair.params.exponent;
    duration_at_unit_speed_.push_back(ElasticContactDuration(pair.params, mass, 1.0));
    duration_speed_exponent_.push_back((1 - n) / (1 + n));
    top_acceleration_.push_back(DriveAcceleration(cm, pair.body));
  }
  has_untagged_ = HasUntaggedContacts(cm);
  scene_step_ = cm.model()->opt.timestep;
  reach_.assign(cm.model()->ngeom, kInfinity);
  in_contact_.assign(cm.pairs().size(), 0);
  pair_damping_.assign(cm.pairs().size(), 0.0);
  settled_rule_ = contacts.options().integrator == mjINT_RK4;
}

AutoTimestep::~AutoTimestep() = default;
AutoTimestep::AutoTimestep(AutoTimestep&&) noexcept = default;

double AutoTimestep::FineStep(int pair, double v) const {
  const LawParams& law = contacts_.model().pairs()[pair].params;
  const double speed = std::max(v, law.min_impact_velocity);
  const double duration =
      duration_at_unit_speed_[pair] * std::pow(speed, duration_speed_exponent_[pair]);
  return duration / LawStepsPerContact(pair);
}

double AutoTimestep::LawStepsPerContact(int pair) const {
  return Law(contacts_.model().pairs()[pair].params.kind).family == LawFamily::kLinear
             ? options_.kelvin_voigt_steps_per_contact
             : options_.steps_per_contact;
}

double AutoTimestep::SettledStep(int pair) const {
  const double floor = contacts_.model().pairs()[pair].params.min_impact_velocity;
  const double duration =
      duration_at_unit_speed_[pair] * std::pow(floor, duration_speed_exponent_[pair]);
  return duration / kSettledStepsPerContact;
}

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
  // its period 2 duration, as a contact's duration, in steps_per_contact
  // steps (the fixed-step rule: kStepsPerContact in either)
  return 2 * duration / options_.steps_per_contact;
}

double AutoTimestep::FrictionLag(mjData* d, size_t first, size_t end) {
  const std::vector<ContactData::Evaluation>& points = contacts_.latest();
  const GeomPair& pair = contacts_.model().pairs()[points[first].pair];
  if (pair.friction.kind == FrictionKind::kNone) return kInfinity;
  const double rate = DampersRate(d, first, end, internal::DamperDirection::kTangential,
                                  [&](const ContactData::Evaluation& e) {
    const double k = e.friction_state.stiffness;
    const double c = TangentialDamping(pair.friction, pair.params, State(e), k, pair.friction_mass);
    return TangentialDynamics(pair.friction, k, c, pair.friction_mass, e.force).damping;
  });
  return rate > 0 ? kFrictionDamperLags / rate : kInfinity;
}

double AutoTimestep::NormalLag(mjData* d, size_t first, size_t end) {
  const LawParams& law = contacts_.model().pairs()[contacts_.latest()[first].pair].params;
  const double rate = DampersRate(d, first, end, internal::DamperDirection::kNormal,
                                  [&](const ContactData::Evaluation& e) {
    return DampingCoefficient(law, State(e));
  });
  return rate > 0 ? kNormalDamperLags / rate : kInfinity;
}

template <typename Damping>
double AutoTimestep::DampersRate(mjData* d, size_t first, size_t end,
                                 internal::DamperDirection direction,
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
    point_damping_.push_back(damping(e));
  }
  return damper_rate_->Rate(contacts_.model().model(), d, pair, static_cast<int>(end - first),
                            point_pos_.data(), point_normal_.data(), point_damping_.data(),
                            direction);
}

ContactState AutoTimestep::State(const ContactData::Evaluation& e) const {
  ContactState state;
  state.depth = e.depth;
  state.depth_rate = e.depth_rate;
  state.impact_velocity = e.impact_velocity;
  state.effective_mass = effective_mass_[e.pair];
  return state;
}

double AutoTimestep::ContactStep(const ContactData::Evaluation& e) const {
  const double floor = contacts_.model().pairs()[e.pair].params.min_impact_velocity;
  const double tangential = TangentialStep(e);
  // a settled contact (it touched barely faster than the law's floor of v0
  // and moves no faster than it): no collision to resolve, only a spring to
  // keep stable under RK4 (rule 5 keeps its damper)
  const double fine = FineStep(e.pair, e.impact_velocity);
  if (settled_rule_ && std::abs(e.depth_rate) <= floor && e.episode >= 0) {
    const double lasted = contacts_.data()->time - contacts_.point_impacts()[e.episode].time_contact;
    const bool slow_touch = e.impact_velocity <= kSettledTouchFactor * floor;
    if (slow_touch || lasted > kSettledDurations * fine * LawStepsPerContact(e.pair)) {
      return std::min(SettledStep(e.pair), tangential);
    }
  }
  // a separation slower than the law's floor of v0 (a resting contact's
  // chatter) is left to the fine step
  if (!(-e.depth_rate > floor)) return std::min(fine, tangential);
  const GeomPair& pair = contacts_.model().pairs()[e.pair];
  const double closing = GravityClosingAcceleration(contacts_.model(), pair, e.normal);
  const double overshoot = kSeparationOvershoot * fine;
  const double separation = TimeToSeparate(e.depth, -e.depth_rate, closing) + overshoot;
  return std::min({separation, fine, tangential});
}

bool AutoTimestep::Closes(const std::array<int, 2>& g, const std::array<int, 2>& body,
                          double top_acceleration, Closing* c) const {
  const ContactModel& cm = contacts_.model();
  const mjModel* m = cm.model();
  const mjData* d = contacts_.data();
  const double rb[2] = {m->geom_rbound[g[0]], m->geom_rbound[g[1]]};
  mjtNum normal[3];  // from geom[0] towards geom[1]
  double spin = 0;   // what rotation adds to the closing speed
  if (m->geom_type[g[0]] == mjGEOM_PLANE && rb[1] > 0) {
    const mjtNum* mat = d->geom_xmat + 9 * g[0];
    normal[0] = mat[2];
    normal[1] = mat[5];
    normal[2] = mat[8];
    mjtNum offset[3];
    mju_sub3(offset, d->geom_xpos + 3 * g[1], d->geom_xpos + 3 * g[0]);
    c->gap = mju_dot3(offset, normal) - rb[1];
    spin = mju_norm3(d->cvel + 6 * body[1]) * rb[1];
  } else if (rb[0] > 0 && rb[1] > 0) {
    mju_sub3(normal, d->geom_xpos + 3 * g[1], d->geom_xpos + 3 * g[0]);
    const double distance = mju_normalize3(normal);
    c->gap = distance - rb[0] - rb[1];
    for (int b = 0; b < 2; ++b) {
      if (!cm.FindDrive(body[b])) spin += mju_norm3(d->cvel + 6 * body[b]) * rb[b];
    }
  } else {
    return false;  // no bounding sphere (planes, height fields)
  }
  mjtNum v[2][3], relative[3];
  for (int b = 0; b < 2; ++b) contacts_.PointVelocity(body[b], d->geom_xpos + 3 * g[b], v[b]);
  mju_sub3(relative, v[0], v[1]);
  c->speed = mju_dot3(relative, normal) + spin;
  c->accel = top_acceleration + GravityClosingAcceleration(cm, body, normal);
  return true;
}

double AutoTimestep::ApproachStep(int p, bool* fine) const {
  const GeomPair& pair = contacts_.model().pairs()[p];
  Closing c;
  if (!Closes(pair.geom, pair.body, top_acceleration_[p], &c)) {
    // always near
    *fine = true;
    return FineStep(p, 0.0);
  }
  const double gap = c.gap;
  const double closing = c.speed;
  const double accel = c.accel;
  const double pair_fine = FineStep(p, SpeedAtTouch(closing, accel, gap));
  const double allowed =
      gap > 0 ? TimeToClose(options_.gap_fraction * gap, closing, accel) : 0.0;
  if (allowed > pair_fine) return allowed;
  // near: fine steps, and the ones that reach the touch end just before and
  // just past it,
  // so that a force that jumps at d = 0+ acts from the start of a step (a
  // touch within a step would act for a fraction of it: an error of the
  // first order in the step)
  *fine = true;
  // bounding spheres that overlap out of contact: no touch to predict
  if (!(gap > 0)) return pair_fine;
  const double touch = TimeToClose(gap, closing, accel);
  // first to just before the touch (the impact speed is read there, before
  // any force), then across it
  const double lead = kTouchOvershoot * pair_fine;
  if (touch > 2 * lead) return std::min(touch - lead, pair_fine);
  return touch + lead;
}

double AutoTimestep::UntaggedStep(int g0, int g1, double margin) const {
  const mjModel* m = contacts_.model().model();
  if (m->geom_type[g0] > m->geom_type[g1]) std::swap(g0, g1);  // a plane first, as GeomPair
  const std::array<int, 2> body = {m->geom_bodyid[g0], m->geom_bodyid[g1]};
  // both welded to the world: their gap never closes
  if (m->body_weldid[body[0]] == 0 && m->body_weldid[body[1]] == 0) return kInfinity;
  Closing c;
  // MuJoCo's contact starts at its margin; a pair within reach (or without
  // bounding spheres) needs the scene's own step
  if (!Closes({g0, g1}, body, DriveAcceleration(contacts_.model(), body), &c) ||
      !(c.gap > margin)) {
    return scene_step_;
  }
  const double allowed = TimeToClose(options_.gap_fraction * (c.gap - margin), c.speed, c.accel);
  return std::max(scene_step_, allowed);
}

void AutoTimestep::SetReach(double bound) {
  const ContactModel& cm = contacts_.model();
  const mjModel* m = cm.model();
  const mjData* d = contacts_.data();
  const double gravity = mju_norm3(m->opt.gravity);
  for (int g = 0; g < m->ngeom; ++g) {
    if (!std::isfinite(bound)) {
      reach_[g] = kInfinity;
      continue;
    }
    // what the geom's surface can move towards another's within bound: its
    // centre's speed, what spin adds, gravity and a drive's acceleration (a
    // pair closes at most at the sum of its geoms'), over gap_fraction,
    // twice for rounding, beyond MuJoCo's margin
    const int body = m->geom_bodyid[g];
    mjtNum v[3];
    contacts_.PointVelocity(body, d->geom_xpos + 3 * g, v);
    double speed = mju_norm3(v);
    if (!cm.FindDrive(body)) speed += mju_norm3(d->cvel + 6 * body) * m->geom_rbound[g];
    double accel = DriveAcceleration(cm, {body, body}) / 2;
    if (!Immovable(cm, body)) accel += gravity;
    const double travel = speed * bound + 0.5 * accel * bound * bound;
    reach_[g] = m->geom_margin[g] + 2 * travel / options_.gap_fraction;
  }
}

double AutoTimestep::Next(mjData* d, double until) {
  const ContactModel& cm = contacts_.model();
  const mjModel* m = cm.model();
  const int npair = static_cast<int>(cm.pairs().size());
  double step = flight_step_;
  bool fine = false;

  // pairs in contact at the last evaluation (a pair may have several
  // points): their fine step
  int in_contact = 0;
  for (const ContactData::Evaluation& e : contacts_.latest()) {
    step = std::min(step, ContactStep(e));
    fine = true;
    if (!in_contact_[e.pair]) {
      in_contact_[e.pair] = 1;
      ++in_contact;
    }
    pair_damping_[e.pair] += DampingCoefficient(cm.pairs()[e.pair].params, State(e));
  }
  // the laws' damping as dampers, a pair's points in parallel: a step no
  // longer than its lag m / c (a contact settling at the v0 floor is stiff:
  // DampingCoefficient)
  for (const ContactData::Evaluation& e : contacts_.latest()) {
    double& c = pair_damping_[e.pair];
    if (c > 0) step = std::min(step, effective_mass_[e.pair] / c);
    c = 0;
  }
  // and friction's dampers, on the inertia at the points (the points come
  // pair by pair); a pair's several points also turn its bodies against the
  // laws' dampers (a box rocking on its corners)
  const size_t points = contacts_.latest().size();
  for (size_t first = 0, end = 0; first < points; first = end) {
    while (end < points && contacts_.latest()[end].pair == contacts_.latest()[first].pair) ++end;
    step = std::min(step, FrictionLag(d, first, end));
    if (end - first > 1) step = std::min(step, NormalLag(d, first, end));
  }

  // the other pairs: the time to close a fraction of their gap, from the
  // current state
  if (in_contact < npair || has_untagged_) {
    mj_kinematics(m, d);
    mj_comPos(m, d);
    mj_comVel(m, d);
    // only the pairs that could close within the step so far (growth
    // included) can shorten it: those whose geoms' reaches overlap
    SetReach(previous_ > 0 ? std::min(step, options_.growth * previous_) : step);
    sweep_->Overlaps(d, reach_, [&](int g0, int g1) {
      const int p = cm.FindPair(g0, g1);
      if (p >= 0) {
        if (!in_contact_[p]) step = std::min(step, ApproachStep(p, &fine));
      } else if (!DefaultContactFilter(m, g0, g1)) {
        // untagged: the scene's step while MuJoCo's contact can reach it
        step = std::min(step, UntaggedStep(g0, g1, std::max(m->geom_margin[g0],
                                                            m->geom_margin[g1])));
      }
    });
    for (int i = 0; i < m->npair; ++i) {
      step = std::min(step, UntaggedStep(m->pair_geom1[i], m->pair_geom2[i], m->pair_margin[i]));
    }
  }

  for (const ContactData::Evaluation& e : contacts_.latest()) in_contact_[e.pair] = 0;
  if (previous_ > 0) step = std::min(step, options_.growth * previous_);
  previous_ = step;  // a cut at `until` does not slow the growth after it
  step = std::min(step, until);
  ++steps_;
  fine_steps_ += fine;
  return step;
}

}  // namespace contactlaws
