// Copyright contactlaws authors.
//
// The narrowphase the laws get (src/mujoco/narrowphase.cc) on the survey's
// configurations (narrowphase_depth_test.cc): box-box, now contactlaws' own,
// is held to the exact depth and witness points on every configuration and
// overlap, while MuJoCo's own box-box still halves; box-mesh and mesh-mesh,
// contactlaws' polytope kernel, to the float vertices; every other pair is
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
#include "geometry/polytope.h"
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

// The survey's mesh is the box given by its 8 vertices as floats: a corner
// is off the box by up to half a float's ulp at 0.1 m, 3.7e-9 m, which is
// 0.37 of the smallest overlap (1e-8 m) and 3.7e-6 of the largest (1e-3 m).
constexpr double kFloatVertex = 3.7e-9;  // m
// The witness is measured along the normal (+z): a corner of a face tilted
// by t that is off by kFloatVertex sideways reads kFloatVertex / tan t off
// the surface along it. The survey's least tilt is 1 degree (tilt1).
// Measured: 1.7e-7 m (tilt1), 3.4e-8 (tilt5), 8.7e-9 (tilt20).
const double kFloatWitness = 2 * kFloatVertex / std::tan(1.0 * M_PI / 180);  // m

TEST_F(Narrowphase, BoxMeshAndMeshMeshAreOursOnEveryConfiguration) {
  for (const auto& [b, t] : {std::pair{mjGEOM_BOX, mjGEOM_MESH}, {mjGEOM_MESH, mjGEOM_MESH}}) {
    for (const Measurement& r : Rows(b, t, Adapter)) {
      SCOPED_TRACE(r.pair + " " + r.config + " " + std::to_string(r.fraction));
      EXPECT_GE(r.ncon, 1);
      EXPECT_LE(r.ncon, contactlaws::kMaxPolytopePoints);
      EXPECT_LT(std::fabs(r.depth_error) * r.exact, 2 * kFloatVertex);
      EXPECT_LT(r.witness * r.exact, kFloatWitness);
    }
    // the face on the face: its 4 corners (MuJoCo: one point)
    const Config& face = FindConfig(b, t, "face");
    EXPECT_EQ(Contacts(b, t, face, 1e-3, Adapter).size(), 4u);
    EXPECT_EQ(Contacts(b, t, face, 1e-3).size(), 1u);
  }
}

TEST_F(Narrowphase, OtherPairsAreMujocosContactForContact) {
  for (const auto& [b, t] : CollidedPairs()) {
    if (b == mjGEOM_BOX && t == mjGEOM_BOX) continue;
    if (t == mjGEOM_MESH && (b == mjGEOM_BOX || b == mjGEOM_MESH)) continue;  // ours
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
