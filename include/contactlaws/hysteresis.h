// Copyright contactlaws authors.
//
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

#ifndef CONTACTLAWS_HYSTERESIS_H_
#define CONTACTLAWS_HYSTERESIS_H_

#include <cmath>

#include "contactlaws/hertz.h"

namespace contactlaws {

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

#endif  // CONTACTLAWS_HYSTERESIS_H_
