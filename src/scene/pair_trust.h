// Copyright contactlaws authors.
//
// How far the depth of each pair of geom types can be trusted, from the
// survey of MuJoCo 2.2.2's narrowphase (docs/geometry.md,
// tests/mujoco/narrowphase_depth_test.cc), and what the library does with it.

#ifndef CONTACTLAWS_SCENE_PAIR_TRUST_H_
#define CONTACTLAWS_SCENE_PAIR_TRUST_H_

#include <string>

namespace contactlaws {

enum class DepthTrust {
  kTrusted,   // MuJoCo's depth is exact to round-off (closed forms)
  kComputed,  // contactlaws computes the contact itself (box-box)
  kWarned,    // depth right where the laws act, but something short of it: a warning
  kRefused,   // depth wrong where the laws act: a tag is refused
};

// The rule that sorts MPR's pairs (its depth error measured by the survey):
// refused when the error reaches kRefusedErrorAtMicron at a 1e-6 m overlap,
// or kRefusedErrorAtTenthMillimetre at 1e-4 m and 1e-3 m, the depths at
// which stiff contacts rest and impacts peak. At n = 1.5 a 1% depth error is
// a 1.5% force error.
inline constexpr double kRefusedErrorAtMicron = 0.10;
inline constexpr double kRefusedErrorAtTenthMillimetre = 0.01;

struct DepthVerdict {
  DepthTrust trust = DepthTrust::kTrusted;
  // for kWarned and kRefused: why, one clause naming the pair type
  std::string reason;
};

// The verdict for two MuJoCo geom types (mjtGeom, either order).
DepthVerdict JudgeDepth(int type1, int type2);

// "plane", "hfield", "sphere", ... for mjtGeom type.
const char* GeomTypeName(int type);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SCENE_PAIR_TRUST_H_
