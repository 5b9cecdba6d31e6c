// Copyright contactlaws authors.

#include "contactlaws/law.h"

#include <algorithm>
#include <cmath>

#include "contactlaws/flores.h"
#include "contactlaws/hertz.h"
#include "contactlaws/hunt_crossley.h"
#include "contactlaws/hysteresis.h"
#include "contactlaws/kelvin_voigt.h"
#include "contactlaws/lankarani_nikravesh.h"

namespace contactlaws {

std::string_view LawName(LawKind kind) {
  switch (kind) {
    case LawKind::kHertz: return "hertz";
    case LawKind::kKelvinVoigt: return "kelvin-voigt";
    case LawKind::kHuntCrossley: return "hunt-crossley";
    case LawKind::kLankaraniNikravesh: return "lankarani-nikravesh";
    case LawKind::kFlores: return "flores";
  }
  return "?";
}

std::optional<LawKind> ParseLawName(std::string_view name) {
  for (LawKind kind : kAllLaws) {
    if (LawName(kind) == name) return kind;
  }
  return std::nullopt;
}

std::string_view LawFormula(LawKind kind) {
  switch (kind) {
    case LawKind::kHertz: return "F = K d^n";
    case LawKind::kKelvinVoigt: return "F = k d + c d'";
    case LawKind::kHuntCrossley: return "F = K d^n (1 + 3(1-e)/2 * d'/v0)";
    case LawKind::kLankaraniNikravesh:
      return "F = K d^n (1 + 3(1-e^2)/4 * d'/v0)";
    case LawKind::kFlores: return "F = K d^n (1 + 8(1-e)/(5e) * d'/v0)";
  }
  return "?";
}

std::string_view LawParameters(LawKind kind) {
  switch (kind) {
    case LawKind::kHertz: return "stiffness K (N/m^n) > 0, exponent n in [1, 3] (default 1.5)";
    case LawKind::kKelvinVoigt:
      return "linear_stiffness k (N/m) > 0, restitution e in [0, 1] "
             "(c = 2 zeta(e) sqrt(k m_eff)) or damping c (N s/m) >= 0";
    case LawKind::kHuntCrossley:
    case LawKind::kLankaraniNikravesh:
      return "stiffness K (N/m^n) > 0, exponent n in [1, 3], restitution e in [0, 1]";
    case LawKind::kFlores:
      return "stiffness K (N/m^n) > 0, exponent n in [1, 3], restitution e in (0, 1]";
  }
  return "?";
}

std::string_view LawReference(LawKind kind) {
  switch (kind) {
    case LawKind::kHertz:
      return "H. Hertz, On the contact of solids (1896); Flores et al. (2011) eq. 1";
    case LawKind::kKelvinVoigt:
      return "Y. A. Khulief, A. A. Shabana, Mech. Mach. Theory 22:213-224 (1987); "
             "Flores et al. (2011) eq. 4";
    case LawKind::kHuntCrossley:
      return "K. H. Hunt, F. R. E. Crossley, J. Appl. Mech. 42:440-445 (1975); "
             "Flores et al. (2011) eqs. 6-7";
    case LawKind::kLankaraniNikravesh:
      return "H. M. Lankarani, P. E. Nikravesh, J. Mech. Des. 112:369-376 (1990); "
             "Flores et al. (2011) eqs. 8-9";
    case LawKind::kFlores:
      return "P. Flores, M. Machado, M. T. Silva, J. M. Martins, Multibody Syst. Dyn. "
             "25:357-375 (2011), eqs. 43-44";
  }
  return "?";
}

double HysteresisCoefficient(LawKind kind, double restitution) {
  switch (kind) {
    case LawKind::kHuntCrossley: return HuntCrossleyCoefficient(restitution);
    case LawKind::kLankaraniNikravesh:
      return LankaraniNikraveshCoefficient(restitution);
    case LawKind::kFlores: return FloresCoefficient(restitution);
    case LawKind::kHertz:
    case LawKind::kKelvinVoigt: return 0.0;
  }
  return 0.0;
}

namespace {

bool IsHertzFamily(LawKind kind) { return kind != LawKind::kKelvinVoigt; }

// A finite value in [lo, hi] (open ends where asked).
bool InRange(double v, double lo, double hi, bool lo_open = false,
             bool hi_open = false) {
  if (!std::isfinite(v)) return false;
  if (lo_open ? v <= lo : v < lo) return false;
  if (hi_open ? v >= hi : v > hi) return false;
  return true;
}

}  // namespace

std::optional<ParamError> ValidateLawParams(const LawParams& p) {
  if (p.kind == LawKind::kFlores) {
    if (!InRange(p.restitution, 0.0, 1.0, /*lo_open=*/true)) {
      return ParamError{"restitution", p.restitution,
                        "must be in (0, 1] for flores"};
    }
  } else if (!InRange(p.restitution, 0.0, 1.0)) {
    return ParamError{"restitution", p.restitution, "must be in [0, 1]"};
  }
  if (IsHertzFamily(p.kind)) {
    if (!InRange(p.stiffness, 0.0, HUGE_VAL, /*lo_open=*/true)) {
      return ParamError{"stiffness", p.stiffness, "must be > 0 (N/m^n)"};
    }
    if (!InRange(p.exponent, 1.0, 3.0)) {
      return ParamError{"exponent", p.exponent, "must be in [1, 3]"};
    }
  } else {
    if (!InRange(p.linear_stiffness, 0.0, HUGE_VAL, /*lo_open=*/true)) {
      return ParamError{"linear_stiffness", p.linear_stiffness,
                        "must be > 0 (N/m)"};
    }
  }
  if (p.damping && !InRange(*p.damping, 0.0, HUGE_VAL)) {
    return ParamError{"damping", *p.damping, "must be >= 0 (N s/m)"};
  }
  if (!InRange(p.min_impact_velocity, 0.0, HUGE_VAL, /*lo_open=*/true)) {
    return ParamError{"min_impact_velocity", p.min_impact_velocity,
                      "must be > 0 (m/s)"};
  }
  return std::nullopt;
}

ContactForce EvaluateLaw(const LawParams& p, const ContactState& s) {
  ContactForce f;
  if (s.depth <= 0.0) return f;

  // spring and damper of the law
  if (p.kind == LawKind::kKelvinVoigt) {
    const double c =
        p.damping ? *p.damping
                  : KelvinVoigtDamping(p.linear_stiffness, s.effective_mass,
                                       p.restitution);
    f.elastic = p.linear_stiffness * s.depth;
    f.total = KelvinVoigtForce(p.linear_stiffness, c, s.depth, s.depth_rate);
  } else {
    const double a = HysteresisCoefficient(p.kind, p.restitution);
    f.elastic = HertzForce(p.stiffness, p.exponent, s.depth);
    f.total = HysteresisForce(p.stiffness, p.exponent, a, s.depth,
                              s.depth_rate, s.impact_velocity);
  }

  // a contact pushes, it does not pull
  if (!p.allow_tension) f.total = std::max(f.total, 0.0);
  return f;
}

double ElasticEnergy(const LawParams& p, double depth) {
  if (depth <= 0.0) return 0.0;
  if (p.kind == LawKind::kKelvinVoigt) {
    return 0.5 * p.linear_stiffness * depth * depth;
  }
  return HertzEnergy(p.stiffness, p.exponent, depth);
}

double ExactRebound(double a) {
  if (a <= 0.0) return 1.0;
  // small a: the terms of g below cancel to O(a^2); expanding e = 1 - delta
  // gives delta = 2a/3 - 4a^2/9 + O(a^3)
  if (a < 1e-4) return 1.0 - 2.0 * a / 3.0 + 4.0 * a * a / 9.0;
  // g(e) = a (1 + e) - ln((1 + a) / (1 - a e)) is concave in e, with g(0) > 0
  // (a > ln(1 + a)) and g -> -inf as e -> 1/a: bisect on (0, min(1, 1/a)).
  auto g = [a](double e) { return a * (1.0 + e) - std::log1p(a) + std::log1p(-a * e); };
  double lo = 0.0;
  double hi = std::min(1.0, 1.0 / a);
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace contactlaws
