// Copyright contactlaws authors.
//
// Flores et al. law (paper eqs. 43-44):
//   F = K d^n (1 + 8 (1 - e) / (5 e) * d'/v0)
// K: N/m^n (> 0); n: exponent; e: restitution in (0, 1]; v0: impact velocity
// (m/s). Valid over the whole range of e: the damping grows without bound as
// e -> 0 (a perfectly plastic contact), so e = 0 itself is refused.
// Convention: see law.h and hysteresis.h.
// Reference: P. Flores, M. Machado, M. T. Silva, J. M. Martins, Multibody
// Syst. Dyn. 25:357-375 (2011).

#ifndef CONTACTLAWS_FLORES_H_
#define CONTACTLAWS_FLORES_H_

namespace contactlaws {

// a(e) = 8 (1 - e) / (5 e), e > 0.
constexpr double FloresCoefficient(double restitution) {
  return 8.0 * (1.0 - restitution) / (5.0 * restitution);
}

}  // namespace contactlaws

#endif  // CONTACTLAWS_FLORES_H_
