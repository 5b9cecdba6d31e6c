// Copyright contactlaws authors.
//
// Lankarani-Nikravesh law (paper eqs. 8-9):
//   F = K d^n (1 + 3 (1 - e^2) / 4 * d'/v0)
// K: N/m^n (> 0); n: exponent; e: restitution in [0, 1]; v0: impact velocity
// (m/s). Derived from the energy loss for e close to 1 (hard contacts).
// Convention: see law.h and hysteresis.h.
// Reference: H. M. Lankarani, P. E. Nikravesh, "A contact force model with
// hysteresis damping for impact analysis of multibody systems", J. Mech. Des.
// 112:369-376 (1990).

#ifndef CONTACTLAWS_LANKARANI_NIKRAVESH_H_
#define CONTACTLAWS_LANKARANI_NIKRAVESH_H_

namespace contactlaws {

// a(e) = 3 (1 - e^2) / 4.
constexpr double LankaraniNikraveshCoefficient(double restitution) {
  return 0.75 * (1.0 - restitution * restitution);
}

}  // namespace contactlaws

#endif  // CONTACTLAWS_LANKARANI_NIKRAVESH_H_
