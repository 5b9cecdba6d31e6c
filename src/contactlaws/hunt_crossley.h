// Copyright contactlaws authors.
//
// Hunt-Crossley law (paper eqs. 6-7):
//   F = K d^n (1 + 3 (1 - e) / 2 * d'/v0)
// K: N/m^n (> 0); n: exponent; e: restitution in [0, 1]; v0: impact velocity
// (m/s). Derived for e close to 1: at low e it dissipates too little (the
// rebound e_post exceeds e), and at e = 0 the damping stays finite.
// Convention: see law.h and hysteresis.h.
// Reference: K. H. Hunt, F. R. E. Crossley, "Coefficient of restitution
// interpreted as damping in vibroimpact", J. Appl. Mech. 42:440-445 (1975).

#ifndef CONTACTLAWS_HUNT_CROSSLEY_H_
#define CONTACTLAWS_HUNT_CROSSLEY_H_

namespace contactlaws {

// a(e) = 3 (1 - e) / 2.
constexpr double HuntCrossleyCoefficient(double restitution) {
  return 1.5 * (1.0 - restitution);
}

}  // namespace contactlaws

#endif  // CONTACTLAWS_HUNT_CROSSLEY_H_
