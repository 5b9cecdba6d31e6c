// Copyright contactlaws authors.
//
// Continuous contact force laws: the common vocabulary of every law.
//
// Sign convention, the same in every law, every header and every file this
// library writes:
//   depth d        > 0 when the surfaces interpenetrate (m);
//   depth rate d'  > 0 while the surfaces approach, < 0 while they separate (m/s);
//   impact velocity v0 = d' at the first touch of this contact episode (m/s, > 0);
//   force F        >= 0 pushes the two bodies apart (N), along the contact normal.
// For d <= 0 every law returns F = 0. Unless allow_tension is set, F is clamped
// to F >= 0 (a damping term may otherwise pull the bodies together while they
// separate, which a contact cannot do).
//
// The kernels in this directory take plain numbers: no MuJoCo types, no
// globals, no I/O. Reference: P. Flores, M. Machado, M. T. Silva,
// J. M. Martins, "On the continuous contact force models for soft materials in
// multibody dynamics", Multibody Syst. Dyn. 25:357-375 (2011).

#ifndef CONTACTLAWS_LAW_H_
#define CONTACTLAWS_LAW_H_

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace contactlaws {

// A law: the index of its row in the table of laws (Laws(), law_table.cc),
// found by its name (ParseLawName); no law needs an id of its own. The
// value-initialized LawId{} is the first row, hertz.
enum class LawId : int {};

// The three forms a law can take. What a law reads and how it is evaluated
// follows from its family (ReadsRestitution, ReadsDissipation, EvaluateLaw).
enum class LawFamily {
  kHysteresis,  // F = K d^n (1 + a(e) d'/v0) (below); Hertz is a = 0
  // F = K d^n (1 + c d') (below), c the tag's dissipation (s/m), a
  // material constant: the form of Simbody, OpenSim and Drake. It reads no e;
  // its rebound is that of a = c v0, so it depends on the impact speed.
  kConstantDissipation,
  kLinear,      // F = k d + c d' (below)
};

// One row of the table of laws.
struct LawInfo {
  std::string_view name;        // as written in tags and on the command line
  LawFamily family;
  std::string_view formula;     // one line, for help texts and `laws`
  std::string_view parameters;  // the tag keys it reads, with units and ranges
  std::string_view reference;   // citation, and its equations in Flores et al. (2011)
  // a(e) of the hysteresis family (nullptr: a = 0, the law is elastic and
  // ignores e); nullptr for the linear family too.
  double (*hysteresis)(double restitution);
  // The restitution is in [0, 1], or in (0, 1] when e = 0 is refused (a(e)
  // grows without bound as e -> 0).
  bool restitution_excludes_zero;
  LawId id{};  // its index in the table (set by Laws())
};

// Every law, in table order (LawId is the index).
const std::vector<LawInfo>& Laws();
const LawInfo& Law(LawId id);

// Every law's id, in table order.
const std::vector<LawId>& AllLaws();

// The law's name as written in tags and on the command line ("flores", ...).
std::string_view LawName(LawId id);

// "hertz, kelvin-voigt, ...": every name, in table order, for messages.
const std::string& LawNameList();

// Inverse of LawName; nullopt for an unknown name.
std::optional<LawId> ParseLawName(std::string_view name);

// Default floor of the impact velocity v0 (m/s): keeps d'/v0 finite for a
// contact that starts at rest (a ball settling on the floor).
inline constexpr double kDefaultMinImpactVelocity = 1e-3;

// Parameters of one law for one pair of geoms, validated once where parsed
// (ValidateLawParams), with what follows from them resolved there too
// (ResolveLawParams). Fields a law does not use are ignored by it.
struct LawParams {
  LawId law{};  // the law these are for; hertz unless set
  double restitution = 1.0;       // e, dimensionless, [0, 1]; (0, 1] for the 1/e laws
  double stiffness = 0.0;         // K, N/m^n, > 0 (hertz family)
  double exponent = 1.5;          // n, dimensionless, [1, 3] (hertz family)
  double linear_stiffness = 0.0;  // k, N/m, > 0 (kelvin-voigt)
  std::optional<double> damping;  // c, N s/m, >= 0 (kelvin-voigt); unset: from e
  std::optional<double> dissipation;  // c, s/m, >= 0 (constant-dissipation family)
  double min_impact_velocity = kDefaultMinImpactVelocity;  // m/s, > 0
  bool allow_tension = false;     // keep F < 0 instead of clamping to 0
  // a(e) of the hysteresis family, dimensionless: HysteresisCoefficient(law,
  // restitution), set by ResolveLawParams; EvaluateLaw reads it.
  double hysteresis = 0.0;
};

// Resolves what follows from the fields set by hand (hysteresis from law and
// restitution): call it after setting them and before EvaluateLaw.
// ContactModel does it for every pair it makes.
void ResolveLawParams(LawParams* params);

// The kinematic state of one contact point, in the convention above.
struct ContactState {
  double depth = 0.0;            // d, m
  double depth_rate = 0.0;       // d', m/s
  double impact_velocity = 0.0;  // v0, m/s (floored by min_impact_velocity)
  double effective_mass = 0.0;   // m_eff along the normal, kg (kelvin-voigt)
};

// A law's force split into its conservative and dissipative parts.
struct ContactForce {
  double total = 0.0;    // F, N (clamped to >= 0 unless allow_tension)
  double elastic = 0.0;  // the spring part alone, N (K d^n or k d)
  // Power dissipated by the contact, W: (total - elastic) * d'. It is >= 0
  // whenever the law dissipates (and the clamp only removes tension).
  double dissipated_power(double depth_rate) const {
    return (total - elastic) * depth_rate;
  }
};

// What is wrong with a parameter: key, offending value, and the valid range,
// e.g. {"restitution", 1.5, "must be in [0, 1]"}.
struct ParamError {
  std::string key;
  double value = 0.0;
  std::string requirement;
};

// Checks the fields law uses; nullopt when valid.
std::optional<ParamError> ValidateLawParams(const LawParams& params);

// The contact force of params.law at state. Pure; params must be valid and
// resolved (ResolveLawParams).
ContactForce EvaluateLaw(const LawParams& params, const ContactState& state);

// Whether EvaluateLaw reads ContactState::effective_mass: Kelvin-Voigt with no
// damping given, whose critical damper is made from it.
bool ReadsEffectiveMass(const LawParams& params);

// Elastic energy stored at depth d (J): K d^(n+1)/(n+1), or k d^2/2.
double ElasticEnergy(const LawParams& params, double depth);

// The law's damping at state as a damper, c = dF/dd' (N s/m, 0 for an
// elastic law or no depth). The hysteresis family's c = a K d^n / v0 is
// largest where v0 is smallest: a contact that settles with v0 at
// min_impact_velocity under a load is a stiff damper, and an explicit step
// longer than about 2.8 of its lags m / c (RK4) hangs it in a false state or
// makes it chatter. Points of a pair add (their dampers act in parallel).
double DampingCoefficient(const LawParams& params, const ContactState& state);

// The elastic contact duration of a law at impact speed v (m/s, > 0) for
// effective mass m (kg), s: HertzContactDuration, or pi sqrt(m/k) for
// Kelvin-Voigt. Infinite for an infinite mass.
double ElasticContactDuration(const LawParams& law, double mass, double speed);

// The depth (m) at which the law's spring carries load (N) at rest: (load /
// K)^(1/n), or load / k (Kelvin-Voigt). 0 for no load.
double RestingDepth(const LawParams& params, double load);

// The lag m / c (s) of a contact at rest under load (N) on mass m (kg): c at
// the depth where the law's spring carries the load, d' = 0, v0 =
// min_impact_velocity. For the hysteresis family c = a load / v0, however
// the load is shared among points. Infinite for an elastic law, no load or
// an infinite mass.
double RestingDamperLag(const LawParams& params, double load, double mass);

// The dimensionless hysteresis coefficient a of the Hertz family, for which
// F = K d^n (1 + a d'/v0): 0 for hertz, the law's a(e) otherwise.
// Not defined for kelvin-voigt nor for the constant-dissipation family, whose
// a = c v0 does not come from e (returns 0).
double HysteresisCoefficient(LawId id, double restitution);

// The restitution e_post the law rebounds with from a first impact at
// restitution e, neglecting gravity during the contact: ExactRebound(a(e)) for
// the hysteresis family; nullopt for the linear family (its clamped force has
// no closed form), for the constant-dissipation family (its rebound,
// ExactRebound(c v0), depends on the impact speed) and for e outside the
// law's range.
std::optional<double> EffectiveRestitution(LawId id, double restitution);

// True for a law that ignores e and dissipates nothing (Hertz).
bool IsElastic(LawId id);

// Whether the law reads the restitution e (every law but Hertz and the
// constant-dissipation family), and the dissipation c (that family alone).
bool ReadsRestitution(LawId id);
bool ReadsDissipation(LawId id);

// The restitution the law reports for an input e: 1 for an elastic law
// (Hertz), which ignores e; none for a law that reads no e and is not elastic
// (constant dissipation); else e.
std::optional<double> ReportedRestitution(LawId id, double restitution);

// ---------------------------------------------------------------------------
// Hertz law (paper eq. 1):
//   F = K d^n
// K: generalized stiffness, N/m^n (> 0); n: exponent (3/2 for two spheres).
// Purely elastic: no energy is dissipated, the rebound restitution is 1.
// For two spheres (paper eqs. 2-3):
//   K = 4 / (3 (s1 + s2)) * sqrt(R1 R2 / (R1 + R2)),  s = (1 - nu^2) / E,
// with a plane taken as a sphere of infinite radius.
// Convention: see law.h (d > 0 in contact, F >= 0 pushes apart).
// Reference: H. Hertz, "On the contact of solids" (1896); paper ref. [44].

// K d^n for d > 0, 0 otherwise (N).
inline double HertzForce(double stiffness, double exponent, double depth) {
  return depth > 0.0 ? stiffness * std::pow(depth, exponent) : 0.0;
}

// Energy stored by the Hertz spring at depth d: K d^(n+1) / (n+1) (J).
inline double HertzEnergy(double stiffness, double exponent, double depth) {
  return depth > 0.0
             ? stiffness * std::pow(depth, exponent + 1.0) / (exponent + 1.0)
             : 0.0;
}

// Compliance s = (1 - nu^2) / E of one material (1/Pa).
inline double MaterialCompliance(double youngs_modulus, double poisson_ratio) {
  return (1.0 - poisson_ratio * poisson_ratio) / youngs_modulus;
}

// K of two spheres of radii r1, r2 (m; infinity for a plane), paper eq. 2,
// in N/m^1.5. s1, s2 from MaterialCompliance.
inline double HertzSphereStiffness(double r1, double r2, double s1, double s2) {
  double effective_radius;
  if (std::isinf(r1)) {
    effective_radius = r2;
  } else if (std::isinf(r2)) {
    effective_radius = r1;
  } else {
    effective_radius = r1 * r2 / (r1 + r2);
  }
  return 4.0 / (3.0 * (s1 + s2)) * std::sqrt(effective_radius);
}

// Greatest depth of an elastic impact at closing speed v of an effective mass
// m (gravity neglected): K d^(n+1)/(n+1) = m v^2/2, so
//   d_max = ((n+1) m v^2 / (2K))^(1/(n+1))   (n = 3/2: (5 m v^2 / (4K))^(2/5)).
inline double HertzMaxDepth(double stiffness, double exponent, double mass, double speed) {
  return std::pow((exponent + 1.0) * mass * speed * speed / (2.0 * stiffness),
                  1.0 / (exponent + 1.0));
}

// Duration of that impact, first touch to separation (s):
//   t_c = 2 (d_max / v) * I_n,  I_n = int_0^1 dx / sqrt(1 - x^(n+1))
//       = B(1/(n+1), 1/2) / (n+1)
// (n = 3/2: t_c = 2.9432 d_max / v). Infinite mass (a body against a fixed or
// driven one only through the other) gives an infinite duration.
inline double HertzContactDuration(double stiffness, double exponent, double mass,
                                   double speed) {
  const double p = 1.0 / (exponent + 1.0);
  const double beta = std::tgamma(p) * std::tgamma(0.5) / std::tgamma(p + 0.5);
  return 2.0 * HertzMaxDepth(stiffness, exponent, mass, speed) / speed * beta * p;
}

// ---------------------------------------------------------------------------
// Kelvin-Voigt law (paper eq. 4):
//   F = k d + c d'
// k: linear stiffness, N/m (> 0); c: damping, N s/m (>= 0). Unless c is given,
//   c = 2 zeta sqrt(k m_eff),  zeta = -ln e / sqrt(pi^2 + ln^2 e)
// (the linear oscillator whose half period rebounds with restitution e;
// e = 1 gives c = 0, e = 0 gives zeta = 1), m_eff the effective mass of the pair
// along the contact normal, kg.
// Unlike the Hertz family the force jumps to c v0 at first touch, and it turns
// negative (tension) before separation: clamped to 0 unless allow_tension.
// Convention: see law.h.
// Reference: paper ref. [46], Y. A. Khulief, A. A. Shabana, Mech. Mach. Theory
// 22:213-224 (1987).

// zeta(e) = -ln e / sqrt(pi^2 + ln^2 e), for e in [0, 1].
inline double KelvinVoigtDampingRatio(double restitution) {
  if (restitution <= 0.0) return 1.0;
  const double log_e = std::log(restitution);
  return -log_e / std::sqrt(M_PI * M_PI + log_e * log_e);
}

// c = 2 zeta sqrt(k m_eff) (N s/m).
inline double KelvinVoigtDamping(double linear_stiffness, double effective_mass,
                                 double restitution) {
  return 2.0 * KelvinVoigtDampingRatio(restitution) *
         std::sqrt(linear_stiffness * effective_mass);
}

// k d + c d' for d > 0, 0 otherwise (N); not clamped.
inline double KelvinVoigtForce(double linear_stiffness, double damping,
                               double depth, double depth_rate) {
  return depth > 0.0 ? linear_stiffness * depth + damping * depth_rate : 0.0;
}

// ---------------------------------------------------------------------------
// The Hertz law with hysteresis damping (paper eq. 5), the form of every law
// of the hysteresis family (law_table.cc):
//   F = K d^n + chi d^n d',  chi = a K / v0,  i.e.  F = K d^n (1 + a d'/v0)
// a: dimensionless hysteresis coefficient, a function of the restitution e
// that each law defines; a = 0 is the Hertz law.
// Convention: see law.h. The force is continuous at d = 0 (it starts and ends
// at zero), unlike Kelvin-Voigt.
//
// Neglecting gravity, a sphere of effective mass m that hits at v0 leaves with
// the rebound e_post that solves (nondimensionalise m x'' = -K x^n (1 + a x'/v0)
// and integrate the energy in the (x', x^(n+1)) plane):
//   a (1 + e_post) = ln((1 + a) / (1 - a e_post))
// whatever K, n, m and v0. ExactRebound() solves it; the tests hold every law
// to it. Its inverse, ExactCoefficient(), is the a(e) of the law `exact`, the
// one whose first rebound is e itself (derivation in docs/laws.md; the
// phase-plane solution is D. W. Marhefka, D. E. Orin, IEEE Trans. Syst. Man
// Cybern. A 29:566-572, 1999).
//
// The constant-dissipation form (Simbody, OpenSim; Drake with n = 1):
//   F = K d^n (1 + c d'),  c in s/m, a material constant,
// is the same equation with a = c v0: it rebounds at ExactRebound(c v0), which
// depends on the impact speed.

// The factors on the Hertz spring K d^n of the two dissipative families, so
// that a caller holding K d^n multiplies it once: 1 + a d'/v0 and 1 + c d'.
inline double HysteresisFactor(double coefficient, double depth_rate, double impact_velocity) {
  return 1.0 + coefficient * depth_rate / impact_velocity;
}
inline double DissipationFactor(double dissipation, double depth_rate) {
  return 1.0 + dissipation * depth_rate;
}

// K d^n (1 + a d'/v0) for d > 0, 0 otherwise (N); not clamped.
inline double HysteresisForce(double stiffness, double exponent,
                              double coefficient, double depth,
                              double depth_rate, double impact_velocity) {
  return HertzForce(stiffness, exponent, depth) *
         HysteresisFactor(coefficient, depth_rate, impact_velocity);
}

// K d^n (1 + c d') for d > 0, 0 otherwise (N); c in s/m; not clamped.
inline double DissipationForce(double stiffness, double exponent, double dissipation,
                               double depth, double depth_rate) {
  return HertzForce(stiffness, exponent, depth) * DissipationFactor(dissipation, depth_rate);
}

// The rebound restitution e_post of a law with coefficient a >= 0: the root in
// (0, 1] of a (1 + e) - ln((1 + a) / (1 - a e)) = 0 (1 for a = 0).
double ExactRebound(double coefficient);

// The inverse: the coefficient a >= 0 whose rebound is e, for e in (0, 1]:
// the positive root of a (1 + e) = ln((1 + a) / (1 - a e)), which lies in
// ((1 - e) / (2e), 1/e); 0 for e >= 1. Near e = 1 (p = 1 - e) it is
// 3p/2 + 3p^2/2 + 27p^3/20 + ...; as e -> 0 it tends to 1/e.
double ExactCoefficient(double restitution);

}  // namespace contactlaws

#endif  // CONTACTLAWS_LAW_H_
