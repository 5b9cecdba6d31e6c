// Copyright contactlaws authors.

#include "scene/tag_keys.h"

namespace contactlaws {

const std::vector<TagKey>& TagKeys() {
  // the defaults are the parameters' own (LawParams, FrictionParams)
  static const std::vector<TagKey> keys = [] {
    const LawParams law;
    const FrictionParams friction;
    using S = internal::PairTagSpec;
    using F = internal::FrictionTagSpec;
    constexpr TagReaders kEvery = TagReaders::kEvery;
    const std::optional<double> none;
    // a name, a number of the law, a number of the friction model
    auto word = [](std::string_view name, TagValue value, std::string S::*field = nullptr) {
      return TagKey{name, value, nullptr, "", kEvery, false, field, nullptr, nullptr, {}};
    };
    auto number = [](std::string_view name, const ParamRange& range, std::string_view unit,
                     TagReaders readers, std::optional<double> S::*field,
                     std::optional<double> fallback) {
      return TagKey{name, TagValue::kNumber, &range, unit, readers, false,
                    nullptr, field, nullptr, fallback};
    };
    auto friction_number = [](std::string_view name, const ParamRange& range,
                              std::string_view unit, TagReaders readers,
                              std::optional<double> F::*field, std::optional<double> fallback) {
      return TagKey{name, TagValue::kNumber, &range, unit, readers, false,
                    nullptr, nullptr, field, fallback};
    };
    auto refused_unread = [](TagKey key) {
      key.refused_unread = true;
      return key;
    };
    std::vector<TagKey> rows = {
        word("geom1", TagValue::kGeom, &S::geom1),
        word("geom2", TagValue::kGeom, &S::geom2),
        word("law", TagValue::kLaw),
        // the law (law.h)
        number("restitution", kUnitRange, "", TagReaders::kRestitutionLaws, &S::restitution, none),
        number("stiffness", kPositiveRange, "N/m^n", kEvery, &S::stiffness, none),
        number("exponent", kExponentRange, "", TagReaders::kHertzFamily, &S::exponent,
               law.exponent),
        number("linear_stiffness", kPositiveRange, "N/m", TagReaders::kLinearLaw,
               &S::linear_stiffness, none),
        number("damping", kNonNegativeRange, "N s/m", TagReaders::kLinearLaw, &S::damping, none),
        refused_unread(number("dissipation", kNonNegativeRange, "s/m",
                              TagReaders::kDissipationLaws, &S::dissipation, none)),
        number("min_impact_velocity", kPositiveRange, "m/s", kEvery, &S::min_impact_velocity,
               law.min_impact_velocity),
        word("allow_tension", TagValue::kSwitch),
        // materials, for Hertz's stiffness and Mindlin's ratio
        number("youngs1", kPositiveRange, "Pa", kEvery, &S::youngs1, none),
        number("poisson1", kPoissonRange, "", kEvery, &S::poisson1, none),
        number("youngs2", kPositiveRange, "Pa", kEvery, &S::youngs2, none),
        number("poisson2", kPoissonRange, "", kEvery, &S::poisson2, none),
        // friction (friction.h); mu from the geoms when not given
        word("friction", TagValue::kFriction),
        friction_number("mu", kNonNegativeRange, "", TagReaders::kAnyFriction, &F::mu, none),
        friction_number("mu_static", kNonNegativeRange, "", TagReaders::kAnyFriction,
                        &F::mu_static, none),
        friction_number("mu_kinetic", kNonNegativeRange, "", TagReaders::kAnyFriction,
                        &F::mu_kinetic, none),
        friction_number("stribeck_velocity", kPositiveRange, "m/s", TagReaders::kStribeckCurve,
                        &F::stribeck_velocity, friction.stribeck_velocity),
        friction_number("transition_velocity", kPositiveRange, "m/s", TagReaders::kRegularized,
                        &F::transition_velocity, friction.transition_velocity),
        friction_number("tangential_stiffness", kPositiveRange, "N/m", TagReaders::kStickSpring,
                        &F::tangential_stiffness, none),
        friction_number("tangential_ratio", kPositiveRange, "k_t over dF_n/dd",
                        TagReaders::kStickSpring, &F::tangential_ratio,
                        friction.tangential_ratio),
        friction_number("tangential_damping", kNonNegativeRange, "N s/m",
                        TagReaders::kStickSpring, &F::tangential_damping, none),
        friction_number("tangential_damping_ratio", kUnitRange, "1: critical",
                        TagReaders::kStickSpring, &F::tangential_damping_ratio, none),
        friction_number("bristle_stiffness", kPositiveRange, "1/m, per newton of normal force",
                        TagReaders::kLuGre, &F::bristle_stiffness, friction.bristle_stiffness),
        friction_number("bristle_damping", kNonNegativeRange,
                        "s/m, per newton of normal force", TagReaders::kLuGre,
                        &F::bristle_damping, none),
        friction_number("viscous", kNonNegativeRange, "N s/m", TagReaders::kStribeckCurve,
                        &F::viscous, friction.viscous),
        friction_number("torsional_friction", kNonNegativeRange,
                        "m, the torque cap over the normal force", TagReaders::kAnyFriction,
                        &F::torsional_friction, none),
        friction_number("rolling_friction", kNonNegativeRange,
                        "m, the torque cap over the normal force", TagReaders::kAnyFriction,
                        &F::rolling_friction, none),
    };
    return rows;
  }();
  return keys;
}

const std::vector<std::string_view>& TagKeyNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> all;
    for (const TagKey& key : TagKeys()) all.push_back(key.name);
    return all;
  }();
  return names;
}

const TagKey* FindTagKey(std::string_view name) {
  for (const TagKey& key : TagKeys()) {
    if (key.name == name) return &key;
  }
  return nullptr;
}

bool Reads(const TagKey& key, LawId law, FrictionKind friction) {
  switch (key.readers) {
    case TagReaders::kEvery: return true;
    case TagReaders::kRestitutionLaws: return ReadsRestitution(law);
    case TagReaders::kDissipationLaws: return ReadsDissipation(law);
    case TagReaders::kHertzFamily: return Law(law).family != LawFamily::kLinear;
    case TagReaders::kLinearLaw: return Law(law).family == LawFamily::kLinear;
    case TagReaders::kAnyFriction: return friction != FrictionKind::kNone;
    case TagReaders::kStickSpring:
      return friction == FrictionKind::kCoulomb || friction == FrictionKind::kStribeck;
    case TagReaders::kRegularized: return friction == FrictionKind::kRegularized;
    case TagReaders::kStribeckCurve:
      return friction == FrictionKind::kStribeck || friction == FrictionKind::kLuGre;
    case TagReaders::kLuGre: return friction == FrictionKind::kLuGre;
  }
  return false;
}

}  // namespace contactlaws
