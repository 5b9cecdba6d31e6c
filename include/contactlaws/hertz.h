// Copyright contactlaws authors.
//
// Hertz law (paper eq. 1):
//   F = K d^n
// K: generalized stiffness, N/m^n (> 0); n: exponent (3/2 for two spheres).
// Purely elastic: no energy is dissipated, the rebound restitution is 1.
// For two spheres (paper eqs. 2-3):
//   K = 4 / (3 (s1 + s2)) * sqrt(R1 R2 / (R1 + R2)),  s = (1 - nu^2) / E,
// with a plane taken as a sphere of infinite radius.
// Convention: see law.h (d > 0 in contact, F >= 0 pushes apart).
// Reference: H. Hertz, "On the contact of solids" (1896); paper ref. [44].

#ifndef CONTACTLAWS_HERTZ_H_
#define CONTACTLAWS_HERTZ_H_

#include <cmath>

namespace contactlaws {

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

}  // namespace contactlaws

#endif  // CONTACTLAWS_HERTZ_H_
