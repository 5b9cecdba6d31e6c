// Copyright contactlaws authors.
//
// The narrowphase the laws get (src/mujoco/narrowphase.cc) on the survey's
// configurations (narrowphase_depth_test.cc): box-box, now contactlaws' own,
// is held to the exact depth and witness points on every configuration and
// overlap, while MuJoCo's own box-box still halves; every other pair is
// MuJoCo's, contact for contact; and the verdict per pair type
// (src/scene/pair_trust.cc) follows the survey's measured errors.

#include "mujoco/narrowphase.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "geometry/box_box.h"
#include "mujoco/narrowphase_rig.h"
#include "scene/pair_trust.h"

namespace {

using namespace narrowphase_test;  // NOLINT: the test's own helpers

int Adapter(const mjModel* m, const mjData* d, int g0, int g1, mjContact* con) {
  return contactlaws::Collide(m, d, g0, g1, 0, con);
}

// Depths and witness points to round-off: coordinates near 0.1 m against a
// 1e-8 m overlap (measured worst for the kernel: below 1e-7 relative).
constexpr double kRoundOffRel = 1e-6;

TEST_F(Narrowphase, BoxBoxIsExactOnEveryConfiguration) {
  for (const Measurement& r : Rows(mjGEOM_BOX, mjGEOM_BOX, Adapter)) {
    SCOPED_TRACE(r.config + " " + std::to_string(r.fraction));
    EXPECT_GE(r.ncon, 1);
    EXPECT_LE(r.ncon, contactlaws::kMaxBoxBoxPoints);
    EXPECT_LT(std::fabs(r.depth_error), kRoundOffRel);
    EXPECT_LT(r.witness, kRoundOffRel);
    EXPECT_LT(r.normal_degrees, 1e-6);
  }
  // while MuJoCo's own face path still reports half the overlap
  const Measurement mujoco = Row(mjGEOM_BOX, mjGEOM_BOX, "face", 1e-3);
  EXPECT_NEAR(mujoco.depth / mujoco.exact, 0.5, 1e-6);
}

TEST_F(Narrowphase, BoxBoxHasEachCornerOnceAndNothingOffTheFace) {
  const Config& face = FindConfig(mjGEOM_BOX, mjGEOM_BOX, "face");
  const std::vector<mjContact> corners = Contacts(mjGEOM_BOX, mjGEOM_BOX, face, 1e-3, Adapter);
  ASSERT_EQ(corners.size(), 4u);  // MuJoCo: 9 contacts at 4 corners
  const Config& turned = FindConfig(mjGEOM_BOX, mjGEOM_BOX, "rot45z");
  const Vec3 half = GeomSize(mjGEOM_BOX);
  for (const mjContact& c : Contacts(mjGEOM_BOX, mjGEOM_BOX, turned, 1e-3, Adapter)) {
    // MuJoCo: a contact 4.7 cm beyond the face
    EXPECT_LE(std::fabs(c.pos[0]), half[0] + 1e-12);
    EXPECT_LE(std::fabs(c.pos[1]), half[1] + 1e-12);
  }
}

TEST_F(Narrowphase, OtherPairsAreMujocosContactForContact) {
  for (const auto& [b, t] : CollidedPairs()) {
    if (b == mjGEOM_BOX && t == mjGEOM_BOX) continue;
    const std::vector<Measurement> ours = Rows(b, t, Adapter);
    const std::vector<Measurement> theirs = Rows(b, t);
    ASSERT_EQ(ours.size(), theirs.size());
    for (size_t i = 0; i < ours.size(); ++i) {
      EXPECT_EQ(ours[i].ncon, theirs[i].ncon) << ours[i].pair << " " << ours[i].config;
      EXPECT_EQ(ours[i].depth, theirs[i].depth) << ours[i].pair << " " << ours[i].config;
    }
  }
}

TEST_F(Narrowphase, VerdictPerPairTypeFollowsTheSurvey) {
  // refused exactly when MuJoCo's depth error reaches the rule's bounds
  for (const auto& [b, t] : CollidedPairs()) {
    if (b == mjGEOM_BOX && t == mjGEOM_BOX) continue;
    double micron = 0, tenth = 0;  // worst |error| at 1e-6 m, at 1e-4..1e-3 m
    for (const Measurement& r : Rows(b, t)) {
      const double error = r.ncon == 0 ? 1.0 : std::fabs(r.depth_error);
      if (r.fraction == 1e-5) micron = std::max(micron, error);
      if (r.fraction >= 1e-3) tenth = std::max(tenth, error);
    }
    const bool wrong = micron >= contactlaws::kRefusedErrorAtMicron ||
                       tenth >= contactlaws::kRefusedErrorAtTenthMillimetre;
    const contactlaws::DepthVerdict v = contactlaws::JudgeDepth(b, t);
    EXPECT_EQ(v.trust == contactlaws::DepthTrust::kRefused, wrong)
        << TypeName(b) << "-" << TypeName(t) << ": " << micron << " at 1e-6 m, " << tenth
        << " at 1e-4..1e-3 m";
    // a trusted pair is exact to round-off (or float vertices) everywhere
    if (v.trust == contactlaws::DepthTrust::kTrusted) {
      EXPECT_LT(micron, 1e-6);
    }
  }
}

}  // namespace
