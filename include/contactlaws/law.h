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
  kHysteresis,  // F = K d^n (1 + a(e) d'/v0) (hysteresis.h); Hertz is a = 0
  // F = K d^n (1 + c d') (hysteresis.h), c the tag's dissipation (s/m), a
  // material constant: the form of Simbody, OpenSim and Drake. It reads no e;
  // its rebound is that of a = c v0, so it depends on the impact speed.
  kConstantDissipation,
  kLinear,      // F = k d + c d' (kelvin_voigt.h)
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

}  // namespace contactlaws

#endif  // CONTACTLAWS_LAW_H_
