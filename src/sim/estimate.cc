// Copyright contactlaws authors.

#include "sim/estimate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "contactlaws/law.h"
#include "mujoco/kinematics.h"
#include "contactlaws/contact_model.h"
#include "mujoco/narrowphase.h"

namespace contactlaws {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

bool Immovable(const ContactModel& cm, int body) {
  return cm.model()->body_weldid[body] == 0 || cm.FindDrive(body) != nullptr;
}

namespace {

// Whether body moves as a rigid part of a free-floating tree's root: then it
// falls at g and the root's subtree mass is its translational mass. A body
// on hinges, slides or balls (a pendulum, a plank on a pivot, a block on
// rails) falls as its joints let it, and meets a contact with the mass its
// chain shows there: only stepping ahead tells.
bool FloatsFree(const ContactModel& cm, int body) {
  const mjModel* m = cm.model();
  const int root = m->body_rootid[body];
  return m->body_weldid[body] == root && m->body_jntnum[root] == 1 &&
         m->jnt_type[m->body_jntadr[root]] == mjJNT_FREE;
}

}  // namespace

double GravityClosingAcceleration(const ContactModel& cm, const GeomPair& pair,
                                  const mjtNum normal[3]) {
  return GravityClosingAcceleration(cm, pair.body, normal);
}

double GravityClosingAcceleration(const ContactModel& cm, const std::array<int, 2>& body,
                                  const mjtNum normal[3]) {
  const mjtNum along = mju_dot3(cm.model()->opt.gravity, normal);
  double accel = 0;
  if (!Immovable(cm, body[0])) accel += along;
  if (!Immovable(cm, body[1])) accel -= along;
  return accel;
}

double SpeedAtTouch(double closing, double accel, double gap) {
  if (!(closing > 0 || accel > 0)) return 0;
  const double squared = closing * closing + 2 * accel * std::max(0.0, gap);
  return squared > 0 ? std::sqrt(squared) : 0.0;
}

namespace {

// How far ahead LookAhead steps: enough for a pendulum or a falling body to
// reach what it will hit, short enough for check to answer at once.
constexpr double kLookAheadTime = 2.0;      // s of simulated time
constexpr int kLookAheadSteps = 200000;

// The nearest points of pair at d (the narrowphase with a margin that reaches
// them: the centre distance plus both bounding radii), or nullptr.
const mjContact* Nearest(const mjModel* m, const mjData* d, const GeomPair& pair,
                         const ContactBuffer& found) {
  const int g0 = pair.geom[0];
  const int g1 = pair.geom[1];
  mjtNum centres[3];
  mju_sub3(centres, d->geom_xpos + 3 * g1, d->geom_xpos + 3 * g0);
  const double reach = mju_norm3(centres) + m->geom_rbound[g0] + m->geom_rbound[g1] + 1.0;
  const int count = Collide(m, d, g0, g1, reach, found.get());
  const mjContact* nearest = nullptr;
  for (int i = 0; i < count; ++i) {
    if (!nearest || found[i].dist < nearest->dist) nearest = &found[i];
  }
  return nearest;
}

}  // namespace

std::optional<Approach> LookAhead(const ContactData& contacts, int pair_index) {
  const ContactModel& cm = contacts.model();
  const mjModel* m = cm.model();
  const GeomPair& pair = cm.pairs()[pair_index];
  // a copy of the data, stepped by MuJoCo alone: its tagged pairs are MuJoCo's
  // (no ContactData is registered for it), which changes nothing before the
  // first touch, where the look stops
  UniqueData ahead(mj_makeData(m));
  mjData* d = ahead.get();
  mj_copyData(d, m, contacts.data());
  const ContactBuffer found = MakeContactBuffer();
  const double start = d->time;
  for (int k = 0; k < kLookAheadSteps && d->time - start < kLookAheadTime; ++k) {
    mj_forward(m, d);
    const mjContact* nearest = Nearest(m, d, pair, found);
    if (!nearest) return std::nullopt;
    const double step = m->opt.timestep;
    Approach a;
    a.rate = ApproachRate(cm, d, pair, nearest->pos, nearest->frame, d->qvel, d->time);
    // the next step would bring it in: this state is the last before touch
    if (nearest->dist <= std::max(0.0, a.rate) * step) {
      a.effective_mass = EffectiveMass(m, d, pair, nearest->pos, nearest->frame);
      a.time = d->time - start;
      return a;
    }
    mj_step(m, d);
  }
  return std::nullopt;
}

ContactEstimate EstimateContact(const ContactData& contacts, int pair_index,
                                std::optional<double> impact_velocity) {
  const ContactModel& cm = contacts.model();
  const mjModel* m = cm.model();
  const mjData* d = contacts.data();
  const GeomPair& pair = cm.pairs()[pair_index];
  ContactEstimate e;

  e.effective_mass = PairEffectiveMass(cm, pair_index);

  const ContactBuffer found = MakeContactBuffer();
  const mjContact* nearest = Nearest(m, d, pair, found);

  double speed = 0;
  if (nearest) {
    e.gap = nearest->dist;
    const mjtNum* normal = nearest->frame;  // from geom[0] towards geom[1]
    // driven bodies count with their top speed below, not their current one
    mjtNum v[2][3], relative[3];
    for (int b = 0; b < 2; ++b) {
      if (cm.FindDrive(pair.body[b])) {
        mju_zero3(v[b]);
      } else {
        contacts.PointVelocity(pair.body[b], nearest->pos, v[b]);
      }
    }
    mju_sub3(relative, v[0], v[1]);
    const double closing = mju_dot3(relative, normal);
    speed = SpeedAtTouch(closing, GravityClosingAcceleration(cm, pair, normal), *e.gap);
  }
  for (int body : pair.body) {
    if (const Drive* drive = cm.FindDrive(body)) {
      speed += std::abs(drive->amplitude * drive->omega);
    }
  }
  e.impact_velocity = impact_velocity ? *impact_velocity : speed;
  // nothing closes them by the current speeds and gravity alone (a pendulum,
  // a body on a free body), or a body moves on joints that gravity over the
  // gap does not describe (a plank on a pivot: its tip lands faster than a
  // free fall, with a third of its mass): step ahead to the touch
  const bool small_tag =
      static_cast<int>(cm.tags()[pair.tag].pairs.size()) <= kLookAheadPairs;
  bool articulated = false;
  for (const int body : pair.body) {
    articulated = articulated || (!Immovable(cm, body) && !FloatsFree(cm, body));
  }
  if (!impact_velocity && nearest &&
      (!(speed >= pair.params.min_impact_velocity) || articulated) && small_tag &&
      !Immovable(cm, pair.body[0]) + !Immovable(cm, pair.body[1]) > 0) {
    const std::optional<Approach> a = LookAhead(contacts, pair_index);
    if (a && a->rate >= pair.params.min_impact_velocity) {
      e.impact_velocity = a->rate;
      e.effective_mass = a->effective_mass;
      e.looked_ahead = a->time;
    }
  }

  const LawParams& law = pair.params;
  const double v = e.impact_velocity;
  if (std::isinf(e.effective_mass) || !(v > 0 || Law(law.law).family == LawFamily::kLinear)) {
    e.max_depth = e.contact_duration = kInfinity;
  } else if (Law(law.law).family == LawFamily::kLinear) {
    e.max_depth = v * std::sqrt(e.effective_mass / law.linear_stiffness);
    e.contact_duration = ElasticContactDuration(law, e.effective_mass, v);
  } else {
    e.max_depth = HertzMaxDepth(law.stiffness, law.exponent, e.effective_mass, v);
    e.contact_duration = ElasticContactDuration(law, e.effective_mass, v);
  }
  return e;
}

double PairEffectiveMass(const ContactModel& cm, int pair_index) {
  const mjModel* m = cm.model();
  double inverse_mass = 0;
  for (int body : cm.pairs()[pair_index].body) {
    if (!Immovable(cm, body)) inverse_mass += 1.0 / m->body_subtreemass[m->body_rootid[body]];
  }
  return inverse_mass > 0 ? 1.0 / inverse_mass : kInfinity;
}

TagEstimate EstimateTag(const ContactData& contacts, int tag,
                        std::optional<double> impact_velocity) {
  TagEstimate shortest;
  for (int p : contacts.model().tags()[tag].pairs) {
    const ContactEstimate e = EstimateContact(contacts, p, impact_velocity);
    if (shortest.pair < 0 || e.contact_duration < shortest.estimate.contact_duration) {
      shortest.pair = p;
      shortest.estimate = e;
    }
  }
  return shortest;
}

RestingEstimate EstimateResting(const ContactModel& cm, int pair_index,
                                const ContactEstimate& normal) {
  RestingEstimate r;
  const double mass = normal.effective_mass;
  if (!std::isfinite(mass)) return r;
  r.load = mass * mju_norm3(cm.model()->opt.gravity);
  r.lag = RestingDamperLag(cm.pairs()[pair_index].params, r.load, mass);
  return r;
}

std::string TangentialEstimate::Span() const {
  return stiffness > 0 ? fmt::format("period {:.4g} s", 2 * duration)
                       : fmt::format("lag {:.4g} s", timestep());
}

TangentialEstimate EstimateTangential(const ContactModel& cm, int pair_index,
                                      const ContactEstimate& normal) {
  const GeomPair& pair = cm.pairs()[pair_index];
  const FrictionParams& f = pair.friction;
  TangentialEstimate t;
  t.mass = pair.friction_mass;
  // the deepest the contact gets: the estimate's, or its overlap now
  double depth = std::max(std::isfinite(normal.max_depth) ? normal.max_depth : 0.0,
                          normal.gap ? -*normal.gap : 0.0);
  // the load: the pair's weight, or the spring's force there if larger (an
  // impact: the bristles and the regularized curve stiffen with the load)
  ContactState deepest;
  deepest.depth = depth;
  const double weight = t.mass * mju_norm3(cm.model()->opt.gravity);
  t.normal_force =
      std::max(weight, depth > 0 ? EvaluateLaw(pair.params, deepest).elastic : 0.0);
  // at least the depth of the weight at rest, where Mindlin's spring has a
  // stiffness: bodies placed touching have no impact to estimate, and an
  // overlap of 1e-17 m
  const double rest = RestingDepth(pair.params, weight);
  const bool resting = rest > depth;
  depth = std::max(depth, rest);
  if (f.kind == FrictionKind::kNone) return t;
  const std::string model(FrictionName(f.kind));
  if (f.kind == FrictionKind::kRegularized) {
    t.what = fmt::format("regularized curve ({}, slope 2 mu_s F_n / v_t, v_t {} m/s, F_n {:.4g} N, "
                         "mass {:.4g} kg)", model, f.transition_velocity, t.normal_force, t.mass);
  } else if (f.kind == FrictionKind::kLuGre) {
    t.stiffness = f.bristle_stiffness * t.normal_force;
    t.what = fmt::format("bristles ({}, sigma0 F_n {:.4g} N/m, F_n {:.4g} N, mass {:.4g} kg)",
                         model, t.stiffness, t.normal_force, t.mass);
  } else {
    t.stiffness = TangentialStiffness(f, pair.params, depth);
    t.what = fmt::format("stick spring ({}, k_t {:.4g} N/m{}, mass {:.4g} kg)", model,
                         t.stiffness,
                         f.stiffness_rule == TangentialStiffnessRule::kGiven ? ""
                         : resting              ? " (Mindlin, at the depth of its load at rest)"
                                                : " (Mindlin, at the max depth)",
                         t.mass);
  }
  // c_t at that depth, with the law's v0 of the estimate's impact
  ContactState at;
  at.depth = depth;
  at.impact_velocity = std::max(normal.impact_velocity, pair.params.min_impact_velocity);
  t.damping = TangentialDamping(f, pair.params, at, t.stiffness, t.mass);
  t.duration = TangentialDuration(f, t.stiffness, t.damping, t.mass, t.normal_force);
  return t;
}

}  // namespace contactlaws
