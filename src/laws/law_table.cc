// Copyright contactlaws authors.
//
// The table of laws: one row per law. A law of the hysteresis family
// (F = K d^n (1 + a(e) d'/v0)) is one row here: its name, formula, the keys
// it reads, its citation, a(e), and whether e = 0 is refused. Nothing else in
// the library, the command line or the figure scripts names it (docs/laws.md,
// "Adding a law"). docs/laws.md sets the laws side by side.
//
// Citations marked (*) are as the reviews list them (Machado et al., Mech.
// Mach. Theory 53:99, 2012; da Silva et al., Mech. Mach. Theory 167:104501,
// 2022), not checked against the papers themselves (docs/laws.md).

#include <cmath>

#include "contactlaws/law.h"

namespace contactlaws {
namespace {

// Paper eqs. 6-7: a = 3 (1 - e) / 2.
double HuntCrossley(double e) { return 3.0 * (1.0 - e) / 2.0; }

// Paper eqs. 8-9: a = 3 (1 - e^2) / 4.
double LankaraniNikravesh(double e) { return 3.0 * (1.0 - e * e) / 4.0; }

// Paper eqs. 43-44: a = 8 (1 - e) / (5 e), e > 0.
double Flores(double e) { return 8.0 * (1.0 - e) / (5.0 * e); }

// Herbert & McWhannell (1977): a = 6 (1 - e) / ((2e - 1)^2 + 3)
// = 3 (1 - e) / (2 (1 - e + e^2)), the rebound relation to second order in
// 1 - e (e_post = 0.9009 at 0.9). Finite at e = 0 (a = 1.5, as Hunt-Crossley),
// so it rebounds at 0.49 or more whatever e.
double HerbertMcWhannell(double e) { return 6.0 * (1.0 - e) / ((2.0 * e - 1.0) * (2.0 * e - 1.0) + 3.0); }

// Lee & Wang (1983): a = 3 (1 - e) / 4, as published (one source). Half the
// slope of the exact relation at e = 1: it dissipates about half the energy
// of a near-elastic impact (e_post = 0.9524 at 0.9, 0.6867 at 0.1).
double LeeWang(double e) { return 3.0 * (1.0 - e) / 4.0; }

// Gonthier et al. (2004): a = (1 - e^2) / e, e > 0. Close to the exact a ~ 1/e
// at low e (0.1010 at 0.1); slope 2 at e = 1 over-damps (0.8764 at 0.9).
double Gonthier(double e) { return (1.0 - e * e) / e; }

// Zhiying & Qishao (2006): a = 3 (1 - e^2) exp(2 (1 - e)) / 4, as published
// (one source). Finite at e = 0 (a = 5.54, rebound 0.18 at the least).
double ZhiyingQishao(double e) { return 3.0 * (1.0 - e * e) * std::exp(2.0 * (1.0 - e)) / 4.0; }

// Hu & Guo (2015): a = 3 (1 - e) / (2e), e > 0. Also quoted as 3 (1 - e)/(4e);
// that version rebounds at 0.9474 for e = 0.9 (slope 3/4 at e = 1, half the
// exact one), this one at 0.8999, agreeing with the exact relation to third
// order in 1 - e. Chosen for that (docs/laws.md).
double HuGuo(double e) { return 3.0 * (1.0 - e) / (2.0 * e); }

// Gharib & Hurmuzlu (2012): a = (1 - e) / e, e > 0, meant for low e (0.1111
// at 0.1); slope 1 at e = 1 under-damps (0.9310 at 0.9).
double GharibHurmuzlu(double e) { return (1.0 - e) / e; }

// The law `exact`: a(e) is the root of a (1 + e) = ln((1 + a) / (1 - a e)),
// first rebound e itself, neglecting gravity during the contact
// (ExactCoefficient, law.h, docs/laws.md). Its bisection (about 60
// halvings) runs once per pair, where the parameters are made
// (ResolveLawParams), not at each evaluation.

constexpr char kHertzFamilyKeys[] =
    "stiffness K (N/m^n) > 0, exponent n in [1, 3], restitution e in [0, 1]";
constexpr char kHertzFamilyKeysNoZero[] =
    "stiffness K (N/m^n) > 0, exponent n in [1, 3], restitution e in (0, 1]";
constexpr bool kRefusesZero = true;

}  // namespace

const std::vector<LawInfo>& Laws() {
  // built on first use: other translation units' statics may ask early
  static const std::vector<LawInfo> laws = [] {
    std::vector<LawInfo> rows = {
      {"hertz", LawFamily::kHysteresis, "F = K d^n",
       "stiffness K (N/m^n) > 0, exponent n in [1, 3] (default 1.5)",
       "H. Hertz, On the contact of solids (1896); Flores et al. (2011) eq. 1", nullptr, false},
      {"kelvin-voigt", LawFamily::kLinear, "F = k d + c d'",
       "linear_stiffness k (N/m) > 0, restitution e in [0, 1] "
       "(c = 2 zeta(e) sqrt(k m_eff)) or damping c (N s/m) >= 0",
       "Y. A. Khulief, A. A. Shabana, Mech. Mach. Theory 22:213-224 (1987); "
       "Flores et al. (2011) eq. 4",
       nullptr, false},
      {"hunt-crossley", LawFamily::kHysteresis, "F = K d^n (1 + 3(1-e)/2 * d'/v0)",
       kHertzFamilyKeys,
       "K. H. Hunt, F. R. E. Crossley, J. Appl. Mech. 42:440-445 (1975); "
       "Flores et al. (2011) eqs. 6-7",
       HuntCrossley, false},
      {"lankarani-nikravesh", LawFamily::kHysteresis, "F = K d^n (1 + 3(1-e^2)/4 * d'/v0)",
       kHertzFamilyKeys,
       "H. M. Lankarani, P. E. Nikravesh, J. Mech. Des. 112:369-376 (1990); "
       "Flores et al. (2011) eqs. 8-9",
       LankaraniNikravesh, false},
      {"flores", LawFamily::kHysteresis, "F = K d^n (1 + 8(1-e)/(5e) * d'/v0)",
       kHertzFamilyKeysNoZero,
       "P. Flores, M. Machado, M. T. Silva, J. M. Martins, Multibody Syst. Dyn. "
       "25:357-375 (2011), eqs. 43-44",
       Flores, kRefusesZero},
      {"herbert-mcwhannell", LawFamily::kHysteresis,
       "F = K d^n (1 + 6(1-e)/((2e-1)^2+3) * d'/v0)", kHertzFamilyKeys,
       "R. G. Herbert, D. C. McWhannell, J. Eng. Ind. 99:513-518 (1977) (*)",
       HerbertMcWhannell, false},
      {"lee-wang", LawFamily::kHysteresis, "F = K d^n (1 + 3(1-e)/4 * d'/v0)", kHertzFamilyKeys,
       "T. W. Lee, A. C. Wang, J. Mech. Transm. Autom. Des. 105:534-540 (1983) (*)", LeeWang,
       false},
      {"gonthier", LawFamily::kHysteresis, "F = K d^n (1 + (1-e^2)/e * d'/v0)",
       kHertzFamilyKeysNoZero,
       "Y. Gonthier, J. McPhee, C. Lange, J.-C. Piedboeuf, Multibody Syst. Dyn. 11:209-233 "
       "(2004) (*)",
       Gonthier, kRefusesZero},
      {"zhiying-qishao", LawFamily::kHysteresis,
       "F = K d^n (1 + 3(1-e^2) exp(2(1-e))/4 * d'/v0)", kHertzFamilyKeys,
       "Q. Zhiying, L. Qishao, J. Dyn. Control 4:294-298 (2006, in Chinese) (*)",
       ZhiyingQishao, false},
      {"hu-guo", LawFamily::kHysteresis, "F = K d^n (1 + 3(1-e)/(2e) * d'/v0)",
       kHertzFamilyKeysNoZero,
       "S. Hu, X. Guo, Multibody Syst. Dyn. 35:131-151 (2015) (*); 3(1-e)/(2e), not the "
       "3(1-e)/(4e) also quoted (docs/laws.md)",
       HuGuo, kRefusesZero},
      {"gharib-hurmuzlu", LawFamily::kHysteresis, "F = K d^n (1 + (1-e)/e * d'/v0)",
       kHertzFamilyKeysNoZero,
       "M. Gharib, Y. Hurmuzlu, J. Appl. Mech. 79:064506 (2012) (*)", GharibHurmuzlu,
       kRefusesZero},
      {"exact", LawFamily::kHysteresis,
       "F = K d^n (1 + a d'/v0), a (1 + e) = ln((1 + a)/(1 - a e))", kHertzFamilyKeysNoZero,
       "the rebound relation solved for a (docs/laws.md); its phase-plane solution: "
       "D. W. Marhefka, D. E. Orin, IEEE Trans. Syst. Man Cybern. A 29:566-572 (1999)",
       ExactCoefficient, kRefusesZero},
      {"hunt-crossley-constant", LawFamily::kConstantDissipation, "F = K d^n (1 + c d')",
       "stiffness K (N/m^n) > 0, exponent n in [1, 3], dissipation c (s/m) >= 0",
       "K. H. Hunt, F. R. E. Crossley, J. Appl. Mech. 42:440-445 (1975), c a material "
       "constant: SimTK::HuntCrossleyForce and OpenSim (c = 1.5 x their dissipation), Drake "
       "point contact (n = 1, c = d)",
       nullptr, false},
    };
    for (size_t i = 0; i < rows.size(); ++i) rows[i].id = static_cast<LawId>(i);
    return rows;
  }();
  return laws;
}

}  // namespace contactlaws
