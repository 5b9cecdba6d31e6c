// Copyright contactlaws authors.

#include "contactlaws/friction.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contactlaws {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double Dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double Norm(const double a[3]) { return std::sqrt(Dot(a, a)); }

// 10 x^3 - 15 x^4 + 6 x^5 on [0, 1]: 0 to 1 with zero slope and curvature at
// both ends (Drake's and Simbody's step).
double Step5(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * x * (10 + x * (-15 + 6 * x));
}

// Drake's regularized mu(s), s = |v| / v_t: mu_s s (2 - s) up to s = 1,
// then step5 down to mu_k at s = 3 (MultibodyPlant point contact).
double RegularizedMu(const FrictionParams& p, double speed) {
  const double s = speed / p.transition_velocity;
  if (s < 1) return p.mu_static * s * (2 - s);
  return p.mu_static - (p.mu_static - p.mu_kinetic) * Step5((s - 1) / 2);
}

// Andersson et al. (2007), eq. 1 with delta = 2 and no viscous term.
double StribeckMu(const FrictionParams& p, double speed) {
  const double r = speed / p.stribeck_velocity;
  return p.mu_kinetic + (p.mu_static - p.mu_kinetic) * std::exp(-r * r);
}

FrictionOutput Regularized(const FrictionParams& p, const FrictionInput& in) {
  FrictionOutput out;
  const double speed = Norm(in.slip);
  if (!(speed > 0)) return out;
  const double magnitude = RegularizedMu(p, speed) * in.normal_force;
  for (int i = 0; i < 3; ++i) out.force[i] = -magnitude * in.slip[i] / speed;
  out.sliding = true;
  return out;
}

}  // namespace

double BristleDamping(const FrictionParams& p, double normal_force, double mass) {
  return p.bristle_damping ? *p.bristle_damping * normal_force
                           : 2 * std::sqrt(p.bristle_stiffness * normal_force * mass);
}

namespace {

// The bristles of LuGre, in displacement form: dz = du - sigma0 |du| z / g,
// g = mu(|v|) (the load scales the force, not z). Integrated exactly along
// the straight stretch since the commit, so that a stiff bristle is stable
// at any step: z = z_ss + (z_c - z_ss) exp(-sigma0 |du| / g).
// The bristle damper fades with the slip speed, sigma1 exp(-(v / v_s)^2)
// (Olsson et al. 1998; Astrom and Canudas de Wit 2008): it damps the
// presliding, and a constant one makes the model active (Barabanov and
// Ortega 2000). Constant, it would push sigma1 z' = sigma1 v wherever z is
// away from its steady state at speed: a block launched at 1 m/s took 4 x
// 990 N for the first micrometres of its slide, an impulse of sigma1 x the
// change of z in the model, of sigma1 v h in a step that does not resolve
// the few micrometres over which z settles (g / sigma0 = 5 um): the block
// was thrown up, and the ledger gained 70% of its energy under auto.
FrictionOutput LuGre(const FrictionParams& p, const FrictionInput& in) {
  FrictionOutput out;
  const double speed = Norm(in.slip);
  const double g = std::max(StribeckMu(p, speed), 1e-300);
  const double sigma0 = p.bristle_stiffness;
  const double fn = in.normal_force;
  const double fade = speed / p.stribeck_velocity;
  const double bristle_damping = BristleDamping(p, fn, in.mass) * std::exp(-fade * fade);
  const double du = Norm(in.stretch);
  const double decay = std::exp(-sigma0 * du / g);
  double z[3], zdot[3];
  for (int i = 0; i < 3; ++i) {
    const double steady = du > 0 ? g / sigma0 * in.stretch[i] / du : 0.0;
    z[i] = steady + (in.committed[i] - steady) * decay;
  }
  for (int i = 0; i < 3; ++i) zdot[i] = in.slip[i] - sigma0 * speed * z[i] / g;
  for (int i = 0; i < 3; ++i) {
    out.force[i] = -(fn * sigma0 * z[i] + bristle_damping * zdot[i] + p.viscous * in.slip[i]);
    out.state[i] = z[i];
  }
  out.sliding = Norm(z) > 0.5 * g / sigma0;
  out.stored_energy = 0.5 * fn * sigma0 * Dot(z, z);
  return out;
}

}  // namespace

double NormalStiffness(const LawParams& law, double depth) {
  if (Law(law.law).family == LawFamily::kLinear) return law.linear_stiffness;
  return law.exponent * law.stiffness * std::pow(depth, law.exponent - 1);
}

double MindlinRatio(double youngs1, double poisson1, double youngs2, double poisson2) {
  // normal and shear compliances, summed over the two materials
  auto shear = [](double youngs, double poisson) { return youngs / (2 * (1 + poisson)); };
  const double normal = (1 - poisson1 * poisson1) / youngs1 + (1 - poisson2 * poisson2) / youngs2;
  const double tangential =
      (2 - poisson1) / shear(youngs1, poisson1) + (2 - poisson2) / shear(youngs2, poisson2);
  return 4 * normal / tangential;
}

double TangentialStiffness(const FrictionParams& params, const LawParams& law, double depth) {
  switch (params.stiffness_rule) {
    case TangentialStiffnessRule::kGiven: return params.tangential_stiffness;
    case TangentialStiffnessRule::kNormalRatio:
      return params.tangential_ratio * NormalStiffness(law, depth);
  }
  return 0;
}

double TangentialDamping(const FrictionParams& params, const LawParams& law,
                         const ContactState& state, double stiffness, double mass) {
  switch (params.damping_rule) {
    case TangentialDampingRule::kGiven: return params.tangential_damping;
    case TangentialDampingRule::kRatio:
      return 2 * params.tangential_damping_ratio * std::sqrt(stiffness * mass);
    case TangentialDampingRule::kNormalLaw: {
      // the normal law's damping ratio on k_t: c_n sqrt(k_t / k_n)
      const double normal = state.depth > 0 ? NormalStiffness(law, state.depth) : 0.0;
      return normal > 0 ? DampingCoefficient(law, state) * std::sqrt(stiffness / normal) : 0.0;
    }
  }
  return 0;
}

double SlidingMu(const FrictionParams& params, double speed) {
  switch (params.kind) {
    case FrictionKind::kRegularized: return RegularizedMu(params, speed);
    case FrictionKind::kStribeck:
    case FrictionKind::kLuGre: return StribeckMu(params, speed);
    case FrictionKind::kCoulomb: return params.mu_kinetic;
    case FrictionKind::kNone: return 0;
  }
  return 0;
}

TangentialSpringDamper TangentialDynamics(const FrictionParams& p, double stiffness,
                                          double damping, double mass, double normal_force) {
  const double fn = std::max(normal_force, 0.0);
  TangentialSpringDamper out;
  switch (p.kind) {
    case FrictionKind::kNone: return out;
    case FrictionKind::kCoulomb:
    case FrictionKind::kStribeck:
      out.stiffness = stiffness;
      out.damping = p.viscous + damping;
      break;
    case FrictionKind::kLuGre:
      out.stiffness = p.bristle_stiffness * fn;
      out.damping = p.viscous + BristleDamping(p, fn, mass);
      break;
    case FrictionKind::kRegularized:
      out.damping = 2 * p.mu_static * fn / p.transition_velocity;
      break;
  }
  return out;
}

double TangentialDuration(const FrictionParams& p, double stiffness, double damping,
                          double mass, double normal_force) {
  if (p.kind == FrictionKind::kNone) return kInfinity;
  const TangentialSpringDamper spring =
      TangentialDynamics(p, stiffness, damping, mass, normal_force);
  const double k = spring.stiffness;
  const double c = spring.damping;
  if (!(mass > 0) || !std::isfinite(mass) || !std::isfinite(k) || !std::isfinite(c)) {
    return kInfinity;
  }
  if (k == 0) {
    // a damper has no period: a step follows its lag m / c when it is no
    // longer than the lag (RK4 is stable to 2.8 m / c; on the incline 1e-5 s,
    // one lag, gives the creep of 2.5e-6 s to 1e-9): the duration whose 20
    // steps per period (2 x duration, the callers' rule) are one lag
    constexpr double kLagsPerDuration = 10;
    return c > 0 ? kLagsPerDuration * mass / c : kInfinity;
  }
  // the fastest rate of m x'' + c x' + k x = 0
  const double half = c / (2 * mass);
  const double omega2 = k / mass;
  const double rate = half * half <= omega2 ? std::sqrt(omega2)
                                            : half + std::sqrt(half * half - omega2);
  return rate > 0 ? M_PI / rate : kInfinity;
}

CappedSpringOutput CappedSpring(const CappedSpringInput& in) {
  CappedSpringOutput out;
  const double k = in.stiffness;
  // incremental: the committed value (scaled down with a falling stiffness,
  // so that unloading stores no energy it was not given) minus k du
  const double scale =
      in.committed_stiffness > k && in.committed_stiffness > 0 ? k / in.committed_stiffness : 1.0;
  double trial[3], total[3];
  for (int i = 0; i < 3; ++i) {
    trial[i] = in.committed[i] * scale - k * in.stretch[i];
    total[i] = trial[i] - in.damping * in.rate[i];
  }
  // the spring and its damper together against the cap: a damper that
  // resists the slip cannot hold the contact beyond the limit
  const double size = Norm(total);
  const double limit = in.was_sliding ? in.slide_limit : in.stick_limit;
  if (size > limit) {
    // sliding: the force sits at the cap, and so does the committed spring
    out.sliding = true;
    for (int i = 0; i < 3; ++i) out.force[i] = out.spring[i] = total[i] * limit / size;
  } else {
    // stick: the spring holds, its damper acts
    for (int i = 0; i < 3; ++i) {
      out.spring[i] = trial[i];
      out.force[i] = total[i];
    }
  }
  if (k > 0) out.stored_energy = Dot(out.spring, out.spring) / (2 * k);
  return out;
}

bool ReadsStickState(FrictionKind kind) {
  return kind == FrictionKind::kLuGre || ReadsTangentialSpring(kind);
}

bool ReadsTangentialSpring(FrictionKind kind) {
  return kind == FrictionKind::kCoulomb || kind == FrictionKind::kStribeck;
}

FrictionOutput EvaluateFriction(const FrictionParams& params, const FrictionInput& in) {
  switch (params.kind) {
    case FrictionKind::kNone: return FrictionOutput();
    case FrictionKind::kRegularized: return Regularized(params, in);
    case FrictionKind::kLuGre: return LuGre(params, in);
    case FrictionKind::kCoulomb:
    case FrictionKind::kStribeck: break;
  }
  // coulomb and stribeck: the stick spring, sliding at mu(|v|) F_n
  CappedSpringInput spring;
  for (int i = 0; i < 3; ++i) {
    spring.committed[i] = in.committed[i];
    spring.stretch[i] = in.stretch[i];
    spring.rate[i] = in.slip[i];
  }
  spring.stiffness = in.stiffness;
  spring.committed_stiffness = in.committed_stiffness;
  spring.damping = in.damping;
  spring.stick_limit = params.mu_static * in.normal_force;
  spring.slide_limit = SlidingMu(params, Norm(in.slip)) * in.normal_force;
  spring.was_sliding = in.was_sliding;
  const CappedSpringOutput s = CappedSpring(spring);
  FrictionOutput out;
  for (int i = 0; i < 3; ++i) {
    out.force[i] = s.force[i] - params.viscous * in.slip[i];
    out.state[i] = s.spring[i];
  }
  out.sliding = s.sliding;
  out.stored_energy = s.stored_energy;
  return out;
}

}  // namespace contactlaws
