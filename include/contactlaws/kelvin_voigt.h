// Copyright contactlaws authors.
//
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

#ifndef CONTACTLAWS_KELVIN_VOIGT_H_
#define CONTACTLAWS_KELVIN_VOIGT_H_

#include <cmath>

namespace contactlaws {

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

}  // namespace contactlaws

#endif  // CONTACTLAWS_KELVIN_VOIGT_H_
