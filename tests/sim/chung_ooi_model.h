// Copyright contactlaws authors.
//
// The model of Chung & Ooi's benchmark (Granular Matter 13:643, 2011) on its
// own, for chung_ooi_test: its materials and impacts, the rebound the DEM
// codes' model gives, integrated here in two dimensions from the formulas
// (not from the library's friction kernels; the normal law's force and
// damping come from law.h, verified on their own), the rigid-body rebound
// of gross sliding, and the benchmark's normalized quantities.

#ifndef CONTACTLAWS_TESTS_SIM_CHUNG_OOI_MODEL_H_
#define CONTACTLAWS_TESTS_SIM_CHUNG_OOI_MODEL_H_

#include <algorithm>
#include <cmath>
#include <optional>

#include "contactlaws/law.h"

namespace contactlaws::chung_ooi {

struct Material {
  const char* name;
  double youngs, poisson, density;  // Pa, -, kg/m^3
};
// The benchmark's materials as Yade's scripts of its tests give them (E, nu,
// rho; test 4's mu 0.092, 3.9 m/s, e 0.98; V. Angelidakis, B. Chareyre, R.
// Caulk, 2023; Kratos' scene of test 4 takes the same alumina). The paper
// itself was not read here. Those scripts take R = 2.5 mm; the normalized
// quantities of Hertz-Mindlin do not depend on R.
inline constexpr Material kAlumina{"alumina", 380e9, 0.23, 4000};
inline constexpr Material kAlloy{"aluminium alloy", 70e9, 0.33, 2700};
// test 5's (chung_ooi_reference.h)
inline constexpr Material kSteel{"steel", 208e9, 0.30, 7850};
// The second materials of tests 5 to 8 as the DEM codes' scripts of the
// benchmark give them: polyethylene (test 5; PySPH's chung_test_5.py and
// LIGGGHTS-PFM's test05 agree), nylon (tests 6 and 8; LIGGGHTS-PFM's test06
// and test08, PySPH's chung_test_8.py), copper (test 7; PySPH's
// chung_test_7.py, LIGGGHTS-PFM's test07).
inline constexpr Material kPolyethylene{"polyethylene", 1.0e9, 0.40, 1400};
inline constexpr Material kNylon{"nylon", 2.5e9, 0.40, 1000};
inline constexpr Material kCopper{"copper", 120e9, 0.35, 8900};
inline constexpr double kRadius = 2.55e-3;  // m
// the rigid plane: 1000x the sphere's Young modulus, its Poisson ratio (Yade's
// benchmark scripts do the same)
inline constexpr double kRigid = 1000;
// the sphere starts this far from the other body (m): it touches at once
inline constexpr double kGap = 1e-7;

// One impact: body B (a sphere) moves onto body A (the plane, or a sphere of
// radius ra) along -z at vn, along x at vt, spinning about y at w (rad/s);
// the sphere A, if any, moves the other way (the momentum sums to zero) and
// spins at wa.
struct ImpactCase {
  Material material;
  double mu = 0.092, e = 0.98;
  double vn = 3.9, vt = 0, w = 0;  // body B's, m/s and rad/s
  double ra = INFINITY;            // A's radius: a plane when infinite
  double wa = 0;                   // A's spin, rad/s
  // the sphere A's Young modulus and density over B's (the plane is kRigid
  // times stiffer and does not move)
  double a_stiffer = 1, a_denser = 1;
};

struct Rebound {
  double vt = 0, vn = 0, w = 0;  // body B's centre and spin after the impact
  double wa = 0;                 // A's spin
};

inline double Mass(const Material& m, double r) { return m.density * 4.0 / 3.0 * M_PI * r * r * r; }
inline double Inertia(const Material& m, double r) { return 0.4 * Mass(m, r) * r * r; }
inline double Effective(double a, double b) { return std::isinf(a) ? b : a * b / (a + b); }

// Body A's Young modulus (Pa), mass and moment of inertia: infinite for the plane.
inline double YoungsA(const ImpactCase& c) {
  return (std::isinf(c.ra) ? kRigid : c.a_stiffer) * c.material.youngs;
}
inline double MassA(const ImpactCase& c) {
  return std::isinf(c.ra) ? INFINITY : c.a_denser * Mass(c.material, c.ra);
}
inline double InertiaA(const ImpactCase& c) {
  return std::isinf(c.ra) ? INFINITY : 0.4 * MassA(c) * c.ra * c.ra;
}
// B's mass over A's: A's velocity per B's, the other way (0 for the plane).
inline double Share(const ImpactCase& c) { return Mass(c.material, kRadius) / MassA(c); }

// Test 4's impact: 3.9 m/s at `degrees` from the normal, test 4's mu and e
// (ImpactCase's defaults).
inline ImpactCase Test4Impact(const Material& m, double degrees) {
  ImpactCase c{m};
  c.vn = 3.9 * std::cos(degrees * M_PI / 180);
  c.vt = 3.9 * std::sin(degrees * M_PI / 180);
  return c;
}

// The normal law of the tag below: law=exact, its e, Hertz's K of the materials.
inline LawParams NormalLaw(const ImpactCase& c) {
  LawParams law;
  law.law = *ParseLawName("exact");
  law.restitution = c.e;
  law.stiffness = HertzSphereStiffness(c.ra, kRadius,
                                       MaterialCompliance(YoungsA(c), c.material.poisson),
                                       MaterialCompliance(c.material.youngs, c.material.poisson));
  ResolveLawParams(&law);  // a(e), as ContactModel resolves every pair's
  return law;
}

// The effective mass along the normal, kg.
inline double NormalMass(const ImpactCase& c) {
  return Effective(MassA(c), Mass(c.material, kRadius));
}

inline double ContactDuration(const ImpactCase& c) {
  const LawParams law = NormalLaw(c);
  return HertzContactDuration(law.stiffness, law.exponent, NormalMass(c), c.vn);
}

// The tangential spring of ReferenceImpact: `share` of Mindlin's no-slip
// stiffness 8 G* a, and whether its force is scaled by k_t / k_t,prev while
// k_t falls (Thornton et al. 2011's unloading correction). The defaults are
// the library's spring; share 1/2 without the correction is the spring whose
// rebounds the paper's test 5 curves show (chung_ooi_model_test).
struct TangentialSpring {
  double share = 1;
  bool unloading_correction = true;
};

// The benchmark's model in two dimensions, on its own: Hertz (law.h) along
// the normal, Mindlin's no-slip spring k_t = 8 G* a incremental in the slip
// and capped at mu F_n, its force scaled with k_t while k_t falls (Thornton
// et al. 2011; Di Renzo and Di Maio 2005), damped at the normal law's
// damping ratio, c_t = c_n sqrt(k_t / k_n) (Tsuji et al. 1992). The contact
// point sits midway in the overlap, as MuJoCo puts it: levers R - d/2.
// Semi-implicit Euler at t_c / 20000. `spring_model` varies the tangential
// spring (its defaults are the library's).
inline Rebound ReferenceImpact(const ImpactCase& c, const TangentialSpring& spring_model = {}) {
  const Material& m = c.material;
  const bool plane = std::isinf(c.ra);
  const LawParams law = NormalLaw(c);
  const double nu = m.poisson;
  const double shear = m.youngs / (2 * (1 + nu));
  const double shear_a = YoungsA(c) / (2 * (1 + nu));
  const double g_star = 1 / ((2 - nu) / shear + (2 - nu) / shear_a);
  const double r_star = Effective(c.ra, kRadius);
  const double mb = Mass(m, kRadius), ib = Inertia(m, kRadius);
  const double ma = MassA(c), ia = InertiaA(c);
  const double share = Share(c);
  double vb = c.vt, wb = c.w, va = -share * c.vt, wa = c.wa;
  double vbn = -c.vn, van = share * c.vn;
  double depth = 0, spring = 0, k_prev = 0;
  const double h = ContactDuration(c) / 20000;
  ContactState state;
  state.impact_velocity = c.vn * (1 + share);
  do {
    state.depth = depth;
    state.depth_rate = van - vbn;
    const double fn = depth > 0 ? EvaluateLaw(law, state).total : 0.0;
    const double k_t = spring_model.share * 8 * g_star * std::sqrt(r_star * std::max(depth, 0.0));
    const double k_n = 1.5 * law.stiffness * std::sqrt(std::max(depth, 0.0));
    const double c_t = k_n > 0 ? DampingCoefficient(law, state) * std::sqrt(k_t / k_n) : 0.0;
    if (spring_model.unloading_correction && k_t < k_prev) spring *= k_t / k_prev;
    k_prev = k_t;
    const double lb = kRadius - depth / 2, la = c.ra - depth / 2;
    // the slip of B's contact point on A's
    const double slip = (vb - wb * lb) - (va + (plane ? 0 : wa * la));
    spring -= k_t * slip * h;
    double force = spring - c_t * slip;
    if (std::abs(force) > c.mu * fn) {
      force = std::copysign(c.mu * fn, force);
      spring = force;
    }
    vb += force / mb * h;
    vbn += fn / mb * h;
    wb -= lb * force / ib * h;
    if (!plane) {
      va -= force / ma * h;
      van -= fn / ma * h;
      wa -= la * force / ia * h;
    }
    depth += (van - vbn) * h;
  } while (depth > 0 || vbn < van);
  return {vb, vbn, wb, wa};
}

// The benchmark's quantities of one rebound: B's tangential velocity and
// spin, the contact surface's slip over the normal speed (the tangent of its
// angle) before and after, and the normal restitution.
struct Quantities {
  double vt = 0, w = 0;      // m/s, rad/s
  double tangent_in = 0, tangent_out = 0;
  double restitution = 0;
};

inline Quantities Measure(const ImpactCase& c, const Rebound& r) {
  const double share = Share(c);
  const double la = std::isinf(c.ra) ? 0 : c.ra;
  const double slip_in = (c.vt - c.w * kRadius) - (-share * c.vt + c.wa * la);
  const double approach = c.vn * (1 + share);
  const double slip_out = (r.vt - r.w * kRadius) - (-share * r.vt + r.wa * la);
  const double separation = r.vn * (1 + share);
  return {r.vt, r.w, slip_in / approach, slip_out / separation, separation / approach};
}

// Psi = 2 (1 - nu) / (mu (2 - nu)) x tangent: the normalized angles of
// Maw, Barber and Fawcett (1976) that the benchmark's tests 5 to 8 plot.
inline double Normalized(const ImpactCase& c, double tangent) {
  const double nu = c.material.poisson;
  return 2 * (1 - nu) / (c.mu * (2 - nu)) * tangent;
}

// The rigid-body rebound in gross sliding: the normal impulse J = (1 + e) m*
// v, the tangential one mu J against the slip, the levers R; nullopt when
// the slip would stop (the contact sticks: no closed form).
inline std::optional<Rebound> SlidingRebound(const ImpactCase& c) {
  const bool plane = std::isinf(c.ra);
  const Material& m = c.material;
  const double mb = Mass(m, kRadius), ib = Inertia(m, kRadius);
  const double ma = MassA(c), ia = InertiaA(c);
  const double share = Share(c);
  const double la = plane ? 0 : c.ra;
  const double slip = (c.vt - c.w * kRadius) - (-share * c.vt + c.wa * la);
  const double j = (1 + c.e) * NormalMass(c) * c.vn * (1 + share);
  const double jt = -std::copysign(c.mu * j, slip);
  // the slip's change per unit tangential impulse
  const double mobility = 1 / mb + kRadius * kRadius / ib + (plane ? 0 : 1 / ma + la * la / ia);
  if ((slip + jt * mobility) * slip <= 0) return std::nullopt;
  return Rebound{c.vt + jt / mb, c.e * c.vn, c.w - kRadius * jt / ib,
                 plane ? 0.0 : c.wa - la * jt / ia};
}

}  // namespace contactlaws::chung_ooi

#endif  // CONTACTLAWS_TESTS_SIM_CHUNG_OOI_MODEL_H_
