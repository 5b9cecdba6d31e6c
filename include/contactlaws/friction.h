// Copyright contactlaws authors.
//
// Friction models: the tangential (and rolling and torsional) side of a
// contact point, as pure functions of plain numbers (no MuJoCo types, no
// globals, no I/O), like the normal laws of law.h.
//
// Convention, the same in every model:
//   normal force F_n >= 0 (N), from the pair's normal law;
//   slip v (m/s): the velocity of body[1] relative to body[0] at the contact
//     point, in the tangent plane (world frame vectors, normal component
//     removed by the caller);
//   stretch du (m): the tangential displacement of body[1]'s material point
//     relative to body[0]'s since the last committed step, in the plane;
//   force F (N): the friction force on body[1] (body[0] gets -F); it opposes
//     the slip.
// The tangent plane needs no basis: every vector lives in the world frame,
// projected on the plane of the current normal.
//
// References: F. Marques, P. Flores, J. C. P. Claro, H. M. Lankarani, "A survey
// and comparison of several friction force models for dynamic analysis of
// multibody mechanical systems", Nonlinear Dyn. 86:1407-1443 (2016);
// S. Andersson, A. Soderberg, S. Bjorklund, "Friction models for sliding dry,
// boundary and mixed lubricated contacts", Tribol. Int. 40:580-587 (2007);
// C. Canudas de Wit, H. Olsson, K. J. Astrom, P. Lischinsky, "A new model for
// control of systems with friction", IEEE Trans. Autom. Control 40:419-425
// (1995); R. Featherstone, Rigid Body Dynamics Algorithms (2008), 11.8.

#ifndef CONTACTLAWS_FRICTION_H_
#define CONTACTLAWS_FRICTION_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contactlaws/law.h"

namespace contactlaws {

// A friction model: the index of its row in FrictionModels().
enum class FrictionKind : int {
  kNone = 0,         // no friction (the behaviour of a tag before friction existed)
  kCoulomb = 1,      // stick spring capped at mu_s F_n; slides at mu_k F_n
  kRegularized = 2,  // mu(|v|) of Drake/Simbody: no state, creeps under load
  kStribeck = 3,     // as coulomb, sliding at mu(|v|) of Andersson et al.
  kLuGre = 4,        // bristle state z per contact (Canudas de Wit et al.)
};

// One row of the table of friction models.
struct FrictionInfo {
  std::string_view name;        // as written in tags and on the command line
  std::string_view formula;     // one line
  std::string_view state;       // what it remembers per contact
  std::string_view parameters;  // the tag keys it reads, with units and ranges
  std::string_view reference;
  FrictionKind kind = FrictionKind::kNone;  // its index (set by FrictionModels())
};

const std::vector<FrictionInfo>& FrictionModels();
const FrictionInfo& Friction(FrictionKind kind);
std::string_view FrictionName(FrictionKind kind);
// "none, coulomb, ...": every name, for messages.
const std::string& FrictionNameList();
std::optional<FrictionKind> ParseFrictionName(std::string_view name);

// Defaults (docs/friction.md gives the reasons).
// Drake's default stiction tolerance (MultibodyPlant, 1e-4 m/s) is the slip
// at which the regularized curve reaches mu_s.
inline constexpr double kDefaultTransitionVelocity = 1e-4;  // m/s
// Andersson et al. (2007) put the Stribeck velocity of dry contacts at
// 1e-3 ... 1e-2 m/s; Canudas de Wit et al. (1995) use 1e-3.
inline constexpr double kDefaultStribeckVelocity = 1e-2;  // m/s
// Canudas de Wit et al. (1995) table 1, per newton of normal load:
// sigma0 = 1e5 N/m, sigma1 = sqrt(1e5) N s/m at F_n = 1 N.
inline constexpr double kDefaultBristleStiffness = 1e5;  // 1/m (x F_n: N/m)
// Mindlin (1949): k_t / k_n = 4 G* / E* = 2 (1 - nu) / (2 - nu) for two
// bodies of one material; nu = 0.3 (steel, most metals).
inline constexpr double kDefaultPoisson = 0.3;
inline constexpr double kMindlinRatio = 2 * (1 - kDefaultPoisson) / (2 - kDefaultPoisson);

// Mindlin's no-slip stiffness of two elastic spheres, k_t = 8 G* a, over
// Hertz's normal one, dF_n/dd = 2 E* a (a = sqrt(R* d)): 4 G* / E*, with
// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 and 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2,
// G = E / (2 (1 + nu)), each material with its own Poisson ratio (Pa; nu in
// (-1, 0.5)). R. D. Mindlin, J. Appl. Mech. 16:259 (1949); the DEM codes'
// Hertz-Mindlin (LIGGGHTS, Yade, MFIX-DEM, Lethe) and C. Thornton, S. J.
// Cummins, P. W. Cleary, Powder Technol. 210:189 (2011).
double MindlinRatio(double youngs1, double poisson1, double youngs2, double poisson2);

// How a pair's k_t is made, decided once with its parameters
// (ResolvePairFriction): the tag's k_t, or Mindlin's no-slip spring,
// tangential_ratio x dF_n/dd of the normal law at the depth.
enum class TangentialStiffnessRule { kGiven, kNormalRatio };
// How its c_t is made: the tag's c_t; 2 zeta sqrt(k_t m), zeta the tag's
// tangential_damping_ratio or 1 (critical); or the normal law's own damping
// ratio (a tag of materials without either key).
enum class TangentialDampingRule { kGiven, kRatio, kNormalLaw };

// The friction of one pair, resolved (tag, geoms, overrides) and validated.
struct FrictionParams {
  FrictionKind kind = FrictionKind::kNone;
  double mu_static = 0;    // >= 0
  double mu_kinetic = 0;   // in [0, mu_static]
  double transition_velocity = kDefaultTransitionVelocity;  // m/s > 0 (regularized)
  double stribeck_velocity = kDefaultStribeckVelocity;      // m/s > 0 (stribeck, lugre)
  // k_t: the tag's, or Mindlin's no-slip spring (8 G* a for Hertz spheres of
  // materials)
  TangentialStiffnessRule stiffness_rule = TangentialStiffnessRule::kNormalRatio;
  double tangential_stiffness = 0;  // k_t, N/m > 0 (kGiven)
  // k_t / (dF_n/dd) > 0 (kNormalRatio): the tag's, else MindlinRatio of its
  // materials, else kMindlinRatio (one material of nu = 0.3)
  double tangential_ratio = kMindlinRatio;
  // c_t, m the pair's mass (ContactModel)
  TangentialDampingRule damping_rule = TangentialDampingRule::kRatio;
  double tangential_damping = 0;        // c_t, N s/m >= 0 (kGiven)
  double tangential_damping_ratio = 1;  // zeta in [0, 1] (kRatio); 1: critical
  double bristle_stiffness = kDefaultBristleStiffness;  // sigma0, 1/m > 0 (x F_n)
  // sigma1, s/m >= 0 (x F_n); unset: critical for the bristles at the load and
  // the pair's mass m, 2 sqrt(sigma0 F_n m) N s/m (see FrictionInput::mass)
  std::optional<double> bristle_damping;
  double viscous = 0;      // sigma2, N s/m >= 0 (stribeck, lugre)
  double torsional = 0;    // m >= 0: torsional torque cap / F_n (condim >= 4)
  double rolling = 0;      // m >= 0: rolling torque cap / F_n (condim 6)
};

// What is wrong with a friction parameter (key, value, range), or nullopt.
std::optional<ParamError> ValidateFrictionParams(const FrictionParams& params);

// dF/dd of the normal law's elastic part at depth d > 0, N/m: n K d^(n-1),
// or k (Kelvin-Voigt).
double NormalStiffness(const LawParams& law, double depth);

// k_t of coulomb and stribeck at depth d > 0 (N/m) by params.stiffness_rule:
// the tag's, or Mindlin's no-slip spring tangential_ratio x
// NormalStiffness(law, d). Incremental in
// the kernels (CappedSpring), so that it follows the load history as
// Thornton et al. (2011) and Di Renzo and Di Maio (2005) have it.
double TangentialStiffness(const FrictionParams& params, const LawParams& law, double depth);

// c_t of coulomb and stribeck (N s/m) for the stick spring k_t on mass m (kg),
// by params.damping_rule: the tag's c_t; 2 zeta sqrt(k_t m); or the normal
// law's own damping ratio at state, c_n / (2 sqrt(k_n m)), which makes c_t =
// c_n sqrt(k_t / k_n) whatever m (Tsuji, Tanaka, Ishida, Powder Technol.
// 71:239, 1992; LIGGGHTS' and Yade's Hertz-Mindlin).
double TangentialDamping(const FrictionParams& params, const LawParams& law,
                         const ContactState& state, double stiffness, double mass);

// mu at slip speed s (m/s) while sliding: mu_k (coulomb), Andersson's
// mu_k + (mu_s - mu_k) exp(-(s / v_s)^2) (stribeck, lugre), the regularized
// curve (regularized).
double SlidingMu(const FrictionParams& params, double speed);

// The spring k (N/m) and damper c (N s/m) a contact point's tangential
// dynamics put between its bodies at rest, for the pair's mass m (kg) and
// the normal force F_n (N):
//   coulomb, stribeck: k_t = stiffness (N/m), c_t = damping (N s/m, from
//     TangentialDamping) plus viscous;
//   lugre: the bristles sigma0 F_n, BristleDamping plus viscous;
//   regularized: no spring; its curve's slope at zero slip, c = 2 mu_s F_n /
//     v_t, is a damper;
//   none: neither.
struct TangentialSpringDamper {
  double stiffness = 0;  // N/m
  double damping = 0;    // N s/m
};
TangentialSpringDamper TangentialDynamics(const FrictionParams& params, double stiffness,
                                          double damping, double mass, double normal_force);

// The time scale of a contact's tangential dynamics, s: what the contact
// duration is to the normal law (the auto timestep and the timestep advice
// divide it into steps). pi / r, r the fastest rate (1/s) of the spring k and
// damper c of TangentialDynamics on mass m (kg): r = sqrt(k / m) when c <= 2
// sqrt(k m), else c / 2m + sqrt((c / 2m)^2 - k / m). A damper alone
// (regularized) has no period: the duration is 10 m / c, so that the 20
// steps per period of the callers are its lag m / c each.
// Infinite for none, and where nothing stiffens the contact (no load, no
// stiffness, an infinite mass).
double TangentialDuration(const FrictionParams& params, double stiffness, double damping,
                          double mass, double normal_force);

// LuGre's bristle damper at rest, N s/m: the tag's sigma1 x F_n, or critical
// for the bristle spring sigma0 F_n on the pair's mass, 2 sqrt(sigma0 F_n m).
// The model fades it with the slip speed v: x exp(-(v / v_s)^2), v_s the
// Stribeck velocity (Olsson et al., Eur. J. Control 4:176, 1998), so that it
// damps the presliding and not gross sliding.
double BristleDamping(const FrictionParams& params, double normal_force, double mass);

// A 3-vector spring of the stick state (the tangential force, or a rolling
// or torsional torque), capped at a limit. Incremental: the committed value,
// scaled down with the stiffness when it fell since the commit (an
// unloading Mindlin contact), plus -k x the stretch since the commit.
struct CappedSpringInput {
  double committed[3] = {0, 0, 0};  // value at the last commit, in the plane
  double stretch[3] = {0, 0, 0};    // since the last commit (m or rad)
  double rate[3] = {0, 0, 0};       // its rate (m/s or rad/s)
  double stiffness = 0;             // k now (N/m or N m/rad)
  double committed_stiffness = 0;   // k at the last commit
  double damping = 0;               // c (N s/m or N m s/rad), while sticking
  double stick_limit = 0;           // cap while sticking (N or N m)
  double slide_limit = 0;           // cap while sliding
  bool was_sliding = false;         // at the last commit
};
struct CappedSpringOutput {
  double force[3] = {0, 0, 0};   // on body[1]
  double spring[3] = {0, 0, 0};  // the spring's value, to commit (rescaled to the cap)
  bool sliding = false;
  double stored_energy = 0;      // |spring|^2 / (2k), J
};
CappedSpringOutput CappedSpring(const CappedSpringInput& in);

// The tangential friction of one contact point.
struct FrictionInput {
  double normal_force = 0;     // F_n, N
  double slip[3] = {0, 0, 0};  // m/s, in the plane
  // the stick state of coulomb and stribeck (committed spring force, N) or
  // lugre (committed bristle deflection z, m), in the plane
  double committed[3] = {0, 0, 0};
  double stretch[3] = {0, 0, 0};  // m, in the plane
  bool was_sliding = false;
  double stiffness = 0;             // k_t now, N/m
  double committed_stiffness = 0;   // k_t at the commit
  double damping = 0;               // c_t, N s/m
  // kg, the pair's effective mass: LuGre's bristles are critically damped with
  // it unless bristle_damping is given (sigma1 = sqrt(sigma0) of Canudas de
  // Wit's 1 kg example, x F_n, is 40x critical under a 500 N impact: stiff)
  double mass = 0;
};
struct FrictionOutput {
  double force[3] = {0, 0, 0};  // on body[1], N
  double state[3] = {0, 0, 0};  // to commit (spring force, or z)
  bool sliding = false;
  // J, in the stick spring or the bristles. No dissipated power: what the
  // bodies lose to friction, less the change of this, is dissipated (the
  // ledger's identity, contact_memory.h), for any change of the load.
  double stored_energy = 0;
};
FrictionOutput EvaluateFriction(const FrictionParams& params, const FrictionInput& in);

// What EvaluateFriction reads of a FrictionInput beyond the slip and the load,
// so that a caller computes only that: the stick state (committed, stretch,
// was_sliding, mass) for coulomb, stribeck and lugre; the tangential spring
// (stiffness, committed_stiffness, damping) for coulomb and stribeck.
bool ReadsStickState(FrictionKind kind);
bool ReadsTangentialSpring(FrictionKind kind);

}  // namespace contactlaws

#endif  // CONTACTLAWS_FRICTION_H_
