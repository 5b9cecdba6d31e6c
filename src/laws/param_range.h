// Copyright contactlaws authors.
//
// The ranges of the laws' and friction models' parameters, each stated once:
// the tag parser (scene/tag_keys.cc), ValidateLawParams,
// ValidateFrictionParams, the command line's options and the plugin's
// environment variables all check a value against these and word their
// refusal from them.

#ifndef CONTACTLAWS_LAWS_PARAM_RANGE_H_
#define CONTACTLAWS_LAWS_PARAM_RANGE_H_

#include <cmath>
#include <limits>
#include <string>
#include <string_view>

namespace contactlaws {

// A set of finite values between two bounds, either end open or closed.
struct ParamRange {
  double lo;
  bool lo_open;
  double hi;  // infinity: no upper bound
  bool hi_open;
  std::string_view bounds;  // as messages state it: "[0, 1]", "> 0", ">= 0"

  bool Contains(double v) const {
    return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  // "must be in [0, 1]" or "must be > 0", followed by " (unit)" when a unit
  // is given.
  std::string Requirement(std::string_view unit = {}) const {
    std::string text = "must be ";
    if (bounds[0] == '[' || bounds[0] == '(') text.append("in ");
    text.append(bounds);
    if (!unit.empty()) text.append(" (").append(unit).append(")");
    return text;
  }
};

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// Restitution e, and a damping ratio zeta (1: critical).
inline constexpr ParamRange kUnitRange = {0, false, 1, false, "[0, 1]"};
// e of the laws whose a(e) grows without bound as e -> 0 (LawInfo::restitution_excludes_zero).
inline constexpr ParamRange kUnitRangeWithoutZero = {0, true, 1, false, "(0, 1]"};
// Stiffnesses, velocities, Young's moduli.
inline constexpr ParamRange kPositiveRange = {0, true, kUnbounded, true, "> 0"};
// Dampings, friction coefficients, torque caps.
inline constexpr ParamRange kNonNegativeRange = {0, false, kUnbounded, true, ">= 0"};
// The Hertz family's exponent n.
inline constexpr ParamRange kExponentRange = {1, false, 3, false, "[1, 3]"};
// Poisson's ratio nu of an isotropic elastic material.
inline constexpr ParamRange kPoissonRange = {-1, true, 0.5, true, "(-1, 0.5)"};

}  // namespace contactlaws

#endif  // CONTACTLAWS_LAWS_PARAM_RANGE_H_
