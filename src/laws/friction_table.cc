// Copyright contactlaws authors.
//
// The table of friction models: one row per model (name, formula, state,
// the keys it reads, reference), as the table of laws (law_table.cc).
// docs/friction.md sets them side by side, with the creep each measures.

#include <cmath>

#include "contactlaws/friction.h"
#include "laws/param_range.h"

namespace contactlaws {

const std::vector<FrictionInfo>& FrictionModels() {
  static const std::vector<FrictionInfo> models = [] {
    std::vector<FrictionInfo> rows = {
      {"none", "F = 0", "none", "none",
       "the behaviour of a tagged pair without friction"},
      {"coulomb",
       "stick: F = F_c - k_t du - c_t v, |F| <= mu_s F_n; slide: |F| = mu_k F_n along the "
       "spring",
       "the spring's force, anchored on both bodies (body-frame points), committed per step",
       "mu_static, mu_kinetic (>= 0, kinetic <= static; mu sets both), tangential_stiffness "
       "k_t (N/m > 0; default Mindlin's tangential_ratio x dF_n/dd: 8 G* a from materials, "
       "else 0.82), tangential_damping c_t (N s/m >= 0) or tangential_damping_ratio zeta "
       "([0, 1]; c_t = 2 zeta sqrt(k_t m); default: the normal law's damping ratio from "
       "materials, else 1)",
       "Coulomb with an elastic stick anchor: R. Featherstone, Rigid Body Dynamics Algorithms "
       "(2008) 11.8; P. A. Cundall, O. D. L. Strack, Geotechnique 29:47-65 (1979); "
       "R. D. Mindlin, J. Appl. Mech. 16:259-268 (1949); R. D. Mindlin, H. Deresiewicz, "
       "J. Appl. Mech. 20:327-344 (1953); Y. Tsuji, T. Tanaka, T. Ishida, Powder Technol. "
       "71:239-250 (1992)"},
      {"regularized",
       "F = -mu(|v|) F_n v/|v|; mu = mu_s s(2-s) for s = |v|/v_t < 1, then step5 to mu_k at "
       "s = 3",
       "none", "mu_static, mu_kinetic, transition_velocity v_t (m/s > 0, default 1e-4)",
       "Drake MultibodyPlant's point-contact friction (stiction tolerance v_t); Simbody's "
       "step5; Marques et al., Nonlinear Dyn. 86:1407 (2016)"},
      {"stribeck",
       "as coulomb; slide: |F| = (mu_k + (mu_s - mu_k) exp(-(v/v_s)^2)) F_n + viscous |v|",
       "as coulomb",
       "as coulomb, stribeck_velocity v_s (m/s > 0, default 1e-2), viscous (N s/m >= 0)",
       "S. Andersson, A. Soderberg, S. Bjorklund, Tribol. Int. 40:580-587 (2007)"},
      {"lugre",
       "F = -(F_n (s0 z + s1(v) z') + s2 v), z' = v - s0 |v| z / mu(v), mu(v) as stribeck, "
       "s1(v) = s1 exp(-(v/v_s)^2)",
       "the bristle deflection z (m), a vector in the tangent plane, committed per step",
       "mu_static, mu_kinetic, stribeck_velocity, bristle_stiffness s0 (1/m > 0, x F_n; default "
       "1e5), bristle_damping s1 (s/m >= 0, x F_n; default: critical, 2 sqrt(s0 m / F_n) with m the "
       "pair's mass), viscous s2 (N s/m >= 0)",
       "C. Canudas de Wit, H. Olsson, K. J. Astrom, P. Lischinsky, IEEE Trans. Autom. Control "
       "40:419-425 (1995); s1(v): H. Olsson et al., Eur. J. Control 4:176-195 (1998)"},
    };
    for (size_t i = 0; i < rows.size(); ++i) rows[i].kind = static_cast<FrictionKind>(i);
    return rows;
  }();
  return models;
}

const FrictionInfo& Friction(FrictionKind kind) { return FrictionModels()[static_cast<int>(kind)]; }

std::string_view FrictionName(FrictionKind kind) { return Friction(kind).name; }

const std::string& FrictionNameList() {
  static const std::string list = [] {
    std::string names;
    for (const FrictionInfo& model : FrictionModels()) {
      if (!names.empty()) names += ", ";
      names += model.name;
    }
    return names;
  }();
  return list;
}

std::optional<FrictionKind> ParseFrictionName(std::string_view name) {
  for (const FrictionInfo& model : FrictionModels()) {
    if (model.name == name) return model.kind;
  }
  return std::nullopt;
}

std::optional<ParamError> ValidateFrictionParams(const FrictionParams& p) {
  // each value against its range, in this order; a value its rule does not
  // read passes (as a value in range)
  const bool given_stiffness = p.stiffness_rule == TangentialStiffnessRule::kGiven;
  const bool given_damping = p.damping_rule == TangentialDampingRule::kGiven;
  const std::pair<const char*, double> mu[] = {{"mu_static", p.mu_static},
                                               {"mu_kinetic", p.mu_kinetic}};
  for (const auto& [key, value] : mu) {
    if (!kNonNegativeRange.Contains(value)) {
      return ParamError{key, value, kNonNegativeRange.Requirement()};
    }
  }
  if (p.mu_kinetic > p.mu_static) {
    return ParamError{"mu_kinetic", p.mu_kinetic, "must be in [0, mu_static]"};
  }
  const std::pair<const char*, double> positive[] = {
      {"tangential_ratio", p.tangential_ratio},
      {"transition_velocity", p.transition_velocity},
      {"stribeck_velocity", p.stribeck_velocity},
      {"bristle_stiffness", p.bristle_stiffness},
      {"tangential_stiffness", given_stiffness ? p.tangential_stiffness : 1.0}};
  for (const auto& [key, value] : positive) {
    if (!kPositiveRange.Contains(value)) {
      return ParamError{key, value, kPositiveRange.Requirement()};
    }
  }
  const std::pair<const char*, double> non_negative[] = {
      {"tangential_damping", given_damping ? p.tangential_damping : 0.0},
      {"bristle_damping", p.bristle_damping.value_or(0.0)},
      {"viscous", p.viscous},
      {"torsional_friction", p.torsional},
      {"rolling_friction", p.rolling}};
  for (const auto& [key, value] : non_negative) {
    if (!kNonNegativeRange.Contains(value)) {
      return ParamError{key, value, kNonNegativeRange.Requirement()};
    }
  }
  // beyond critical for the pair's mass: give tangential_damping in N s/m
  if (!kUnitRange.Contains(p.tangential_damping_ratio)) {
    return ParamError{"tangential_damping_ratio", p.tangential_damping_ratio,
                      kUnitRange.Requirement()};
  }
  return std::nullopt;
}

}  // namespace contactlaws
