// Copyright contactlaws authors.

#include "scene/pair_friction.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace contactlaws {

PairFriction ResolvePairFriction(const mjModel* m, int g1, int g2, const internal::PairTagSpec& tag,
                                 const Overrides& overrides) {
  const internal::FrictionTagSpec& spec = tag.friction;
  PairFriction out;
  FrictionParams& p = out.params;
  // MuJoCo 2.2 (mj_contactParam): the larger condim, and each friction
  // coefficient the larger of the two geoms'
  out.condim = std::max(m->geom_condim[g1], m->geom_condim[g2]);
  const double* f1 = m->geom_friction + 3 * g1;
  const double* f2 = m->geom_friction + 3 * g2;
  if (out.condim == 1) {
    // frictionless, as in MuJoCo: the tag's friction keys are not read
    if (!spec.first_key.empty() && !(overrides.friction || overrides.mu)) {
      out.ignored_key = spec.first_key;
    }
    return out;
  }
  p.kind = overrides.friction ? *overrides.friction : spec.kind.value_or(FrictionKind::kCoulomb);
  if (p.kind == FrictionKind::kNone) return out;
  const double geom_mu = std::max(f1[0], f2[0]);
  if (overrides.mu) {
    p.mu_static = p.mu_kinetic = *overrides.mu;
  } else {
    p.mu_static = spec.mu ? *spec.mu : spec.mu_static.value_or(geom_mu);
    p.mu_kinetic = spec.mu ? *spec.mu : spec.mu_kinetic.value_or(p.mu_static);
  }
  // the torque caps: the tag's, else the geoms' (the larger), where condim
  // has them
  if (out.condim >= 4) p.torsional = spec.torsional_friction.value_or(std::max(f1[1], f2[1]));
  if (out.condim >= 6) p.rolling = spec.rolling_friction.value_or(std::max(f1[2], f2[2]));
  const bool torsional_unread = spec.torsional_friction && out.condim < 4;
  if (torsional_unread || (spec.rolling_friction && out.condim < 6)) {
    out.unread_cap = fmt::format(
        "{}={} is not read: the pair's condim is {} ({} resistance needs condim {}, as in MuJoCo)",
        torsional_unread ? "torsional_friction" : "rolling_friction",
        torsional_unread ? *spec.torsional_friction : *spec.rolling_friction, out.condim,
        torsional_unread ? "torsional" : "rolling", torsional_unread ? ">= 4" : "6");
  }
  if (spec.transition_velocity) p.transition_velocity = *spec.transition_velocity;
  if (spec.stribeck_velocity) p.stribeck_velocity = *spec.stribeck_velocity;
  // k_t: the tag's, else Mindlin's no-slip spring, of the tag's ratio, else
  // of its materials, else of one material of nu = 0.3
  if (spec.tangential_stiffness) {
    p.stiffness_rule = TangentialStiffnessRule::kGiven;
    p.tangential_stiffness = *spec.tangential_stiffness;
  }
  if (tag.youngs1) {
    p.tangential_ratio = MindlinRatio(*tag.youngs1, *tag.poisson1, *tag.youngs2, *tag.poisson2);
  }
  if (spec.tangential_ratio) p.tangential_ratio = *spec.tangential_ratio;
  // c_t: the tag's, else of the tag's damping ratio, else the normal law's
  // damping ratio (a tag of materials), else critical (the default ratio)
  if (spec.tangential_damping) {
    p.damping_rule = TangentialDampingRule::kGiven;
    p.tangential_damping = *spec.tangential_damping;
  } else if (spec.tangential_damping_ratio) {
    p.tangential_damping_ratio = *spec.tangential_damping_ratio;
  } else if (tag.youngs1) {
    p.damping_rule = TangentialDampingRule::kNormalLaw;
  }
  if (spec.bristle_stiffness) p.bristle_stiffness = *spec.bristle_stiffness;
  p.bristle_damping = spec.bristle_damping;
  if (spec.viscous) p.viscous = *spec.viscous;
  if (const std::optional<ParamError> e = ValidateFrictionParams(p)) {
    out.error = fmt::format("{}={} {}", e->key, e->value, e->requirement);
    if (e->key == "mu_kinetic" && p.mu_kinetic > p.mu_static) {
      out.error = fmt::format("mu_kinetic={} must be in [0, mu_static={}]{}", p.mu_kinetic,
                              p.mu_static,
                              spec.mu_static ? "" : " (mu_static from the geoms' friction)");
    }
  }
  return out;
}

double PairFrictionMass(const mjModel* m, int body0, int body1, bool inertia) {
  // a body that cannot move (static or driven) adds no mass of its own
  auto mass = [m, inertia](int b) {
    if (m->body_weldid[b] == 0 || m->body_mocapid[b] >= 0) {
      return std::numeric_limits<double>::infinity();
    }
    const double* moments = m->body_inertia + 3 * b;
    return inertia ? std::max({moments[0], moments[1], moments[2]})
                   : m->body_subtreemass[m->body_weldid[b]];
  };
  const double a = mass(body0);
  const double b = mass(body1);
  if (std::isinf(a)) return b;
  if (std::isinf(b)) return a;
  return a * b / (a + b);
}

}  // namespace contactlaws
