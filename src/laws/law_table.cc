// Copyright contactlaws authors.
//
// The table of laws: one row per law. A law of the hysteresis family
// (F = K d^n (1 + a(e) d'/v0)) is one row here: its name, formula, the keys
// it reads, its citation, a(e), and whether e = 0 is refused. Nothing else in
// the library, the command line or the figure scripts names it (README,
// "Adding a law").

#include "contactlaws/law.h"

namespace contactlaws {
namespace {

// Paper eqs. 6-7: a = 3 (1 - e) / 2.
double HuntCrossley(double e) { return 3.0 * (1.0 - e) / 2.0; }

// Paper eqs. 8-9: a = 3 (1 - e^2) / 4.
double LankaraniNikravesh(double e) { return 3.0 * (1.0 - e * e) / 4.0; }

// Paper eqs. 43-44: a = 8 (1 - e) / (5 e), e > 0.
double Flores(double e) { return 8.0 * (1.0 - e) / (5.0 * e); }

constexpr char kHertzFamilyKeys[] =
    "stiffness K (N/m^n) > 0, exponent n in [1, 3], restitution e in [0, 1]";

}  // namespace

const std::vector<LawInfo>& Laws() {
  // built on first use: other translation units' statics may ask early
  static const std::vector<LawInfo> laws = {
    {LawKind::kHertz, "hertz", LawFamily::kHysteresis, "F = K d^n",
     "stiffness K (N/m^n) > 0, exponent n in [1, 3] (default 1.5)",
     "H. Hertz, On the contact of solids (1896); Flores et al. (2011) eq. 1", nullptr, false},
    {LawKind::kKelvinVoigt, "kelvin-voigt", LawFamily::kLinear, "F = k d + c d'",
     "linear_stiffness k (N/m) > 0, restitution e in [0, 1] "
     "(c = 2 zeta(e) sqrt(k m_eff)) or damping c (N s/m) >= 0",
     "Y. A. Khulief, A. A. Shabana, Mech. Mach. Theory 22:213-224 (1987); "
     "Flores et al. (2011) eq. 4",
     nullptr, false},
    {LawKind::kHuntCrossley, "hunt-crossley", LawFamily::kHysteresis,
     "F = K d^n (1 + 3(1-e)/2 * d'/v0)", kHertzFamilyKeys,
     "K. H. Hunt, F. R. E. Crossley, J. Appl. Mech. 42:440-445 (1975); "
     "Flores et al. (2011) eqs. 6-7",
     HuntCrossley, false},
    {LawKind::kLankaraniNikravesh, "lankarani-nikravesh", LawFamily::kHysteresis,
     "F = K d^n (1 + 3(1-e^2)/4 * d'/v0)", kHertzFamilyKeys,
     "H. M. Lankarani, P. E. Nikravesh, J. Mech. Des. 112:369-376 (1990); "
     "Flores et al. (2011) eqs. 8-9",
     LankaraniNikravesh, false},
    {LawKind::kFlores, "flores", LawFamily::kHysteresis, "F = K d^n (1 + 8(1-e)/(5e) * d'/v0)",
     "stiffness K (N/m^n) > 0, exponent n in [1, 3], restitution e in (0, 1]",
     "P. Flores, M. Machado, M. T. Silva, J. M. Martins, Multibody Syst. Dyn. "
     "25:357-375 (2011), eqs. 43-44",
     Flores, true},
  };
  return laws;
}

}  // namespace contactlaws
