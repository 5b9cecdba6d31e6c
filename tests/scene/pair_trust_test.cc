// Copyright contactlaws authors.
//
// What a tag gets for each pair of geom types whose depth MuJoCo 2.2.2 gets
// wrong or short (docs/geometry.md): refused with one line, named or in a
// group; warned once per tag and type; box-box computed by contactlaws.

#include "scene/pair_trust.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "geometry/polytope.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class PairTrustTest : public testing::MujocoTest {
 protected:
  // A scene with a floor, a box, an ellipsoid, a cylinder, two box meshes
  // (group 1: box, ellipsoid; group 2: the meshes) and a ball mesh of 80
  // vertices (beyond kMaxPolytopeVertices), and the given tags.
  UniqueModel Scene(const std::string& tags) {
    return LoadModelString(fmt::format(R"(
<mujoco>
  <asset><mesh name="cube" vertex="-.1 -.1 -.1 .1 -.1 -.1 -.1 .1 -.1 .1 .1 -.1
                                   -.1 -.1 .1 .1 -.1 .1 -.1 .1 .1 .1 .1 .1"/>
    <mesh name="ball" vertex="{}"/></asset>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body pos="0 0 1"><freejoint/><geom name="box" type="box" size=".1 .1 .1" group="1"/></body>
    <body pos="1 0 1"><freejoint/><geom name="egg" type="ellipsoid" size=".1 .08 .05" group="1"/></body>
    <body pos="2 0 1"><freejoint/><geom name="can" type="cylinder" size=".1 .05"/></body>
    <body pos="3 0 1"><freejoint/><geom name="mesh1" type="mesh" mesh="cube" group="2"/></body>
    <body pos="4 0 1"><freejoint/><geom name="mesh2" type="mesh" mesh="cube" group="2"/></body>
    <body pos="5 0 1"><freejoint/><geom name="ball" type="mesh" mesh="ball"/></body>
  </worldbody>
  <custom>{}</custom>
</mujoco>)", BallVertices(), tags), "pairs.xml");
  }

  // 80 points spread over a sphere of radius 0.1 (Fibonacci): all on its hull
  static std::string BallVertices() {
    constexpr int kCount = 80;
    std::string out;
    for (int i = 0; i < kCount; ++i) {
      const double z = 1 - (2 * i + 1.0) / kCount, r = std::sqrt(1 - z * z);
      const double t = 2.399963229728653 * i;  // the golden angle
      out += fmt::format("{} {} {} ", 0.1 * r * std::cos(t), 0.1 * r * std::sin(t), 0.1 * z);
    }
    return out;
  }

  // The message a scene is refused with, or "accepted".
  std::string Refusal(const std::string& tags) {
    UniqueModel m = Scene(tags);
    try {
      ContactModel cm(m.get(), "pairs.xml");
    } catch (const Error& e) {
      return e.what();
    }
    return "accepted";
  }
};

constexpr const char* kEllipsoidBox =
    "ellipsoid-box: MuJoCo 2.2.2 gives its depth by MPR (libccd), 78% short at 1e-6 m, 46% deep "
    "at 1e-3 m (docs/geometry.md): the laws would act on a wrong depth; use other geom types, or "
    "leave the pair untagged";

TEST_F(PairTrustTest, NamedPairOfAWrongDepthTypeIsRefused) {
  EXPECT_EQ(Refusal(R"(<text name="contactlaw:p" data="geom1=box geom2=egg law=hertz stiffness=1e8"/>)"),
            std::string("pairs.xml: contactlaw:p: (box, egg): ") + kEllipsoidBox);
}

TEST_F(PairTrustTest, GroupTagWithAWrongDepthTypeIsRefusedNotSkipped) {
  // skipped, the box-ellipsoid pair would get MuJoCo's own contact unsaid
  EXPECT_EQ(Refusal(R"(<text name="contactlaw:g" data="geom1=group:1 geom2=group:1 law=hertz stiffness=1e8"/>)"),
            std::string("pairs.xml: contactlaw:g: (box, egg): ") + kEllipsoidBox);
}

TEST_F(PairTrustTest, LimitedTypesAreWarnedOncePerTagAndType) {
  UniqueModel m = Scene(R"(
    <text name="contactlaw:floor" data="geom1=floor geom2=group:2 law=hertz stiffness=1e8"/>
    <text name="contactlaw:meshes" data="geom1=mesh1 geom2=ball law=hertz stiffness=1e8"/>
    <text name="contactlaw:can" data="geom1=can geom2=box law=hertz stiffness=1e8"/>)");
  const ContactModel cm(m.get(), "pairs.xml");
  ASSERT_EQ(cm.pairs().size(), 4u);
  ASSERT_EQ(cm.warnings().size(), 3u);
  EXPECT_EQ(cm.warnings()[0],
            "pairs.xml: contactlaw:floor: (floor, mesh1): plane-mesh: MuJoCo 2.2.2 returns at "
            "most 3 points, so a mesh face resting on the plane is held at 3 of its corners; "
            "depths exact (docs/geometry.md)");
  EXPECT_EQ(cm.warnings()[1],
            "pairs.xml: contactlaw:meshes: (mesh1, ball): mesh-mesh: a mesh hull beyond 64 "
            "vertices or 124 triangles is left to MuJoCo 2.2.2, which returns one point, so a "
            "face resting on a face is held at one point; depths exact (docs/geometry.md)");
  EXPECT_EQ(cm.warnings()[2].rfind("pairs.xml: contactlaw:can: (can, box): cylinder-box: its "
                                   "depth comes from MPR (libccd)", 0), 0u);
}

TEST_F(PairTrustTest, BoxBoxIsComputedWithoutAWord) {
  UniqueModel m = Scene(R"(<text name="contactlaw:b" data="geom1=box geom2=floor law=hertz stiffness=1e8"/>
                           <text name="contactlaw:bb" data="geom1=box geom2=ball law=hertz stiffness=1e8"/>)");
  const ContactModel cm(m.get(), "pairs.xml");
  EXPECT_EQ(JudgeDepth(mjGEOM_BOX, mjGEOM_BOX).trust, DepthTrust::kComputed);
  EXPECT_EQ(JudgeDepth(mjGEOM_PLANE, mjGEOM_BOX).trust, DepthTrust::kTrusted);
  ASSERT_EQ(cm.warnings().size(), 1u);  // box-mesh beyond the caps, not box-plane
  EXPECT_NE(cm.warnings()[0].find("box-mesh"), std::string::npos);
}

TEST_F(PairTrustTest, MeshesWithinThePolytopeCapsAreComputedWithoutAWord) {
  UniqueModel m = Scene(R"(<text name="contactlaw:bm" data="geom1=box geom2=mesh1 law=hertz stiffness=1e8"/>
                           <text name="contactlaw:mm" data="geom1=mesh1 geom2=mesh2 law=hertz stiffness=1e8"/>)");
  const ContactModel cm(m.get(), "pairs.xml");
  EXPECT_TRUE(cm.warnings().empty()) << cm.warnings()[0];
  for (const auto& pair : cm.pairs()) EXPECT_EQ(pair.slots, kMaxPolytopePoints);
}

TEST(PairTrust, VerdictIsTheSameInEitherOrder) {
  for (int a = 0; a < mjNGEOMTYPES; ++a) {
    for (int b = 0; b < mjNGEOMTYPES; ++b) {
      EXPECT_EQ(JudgeDepth(a, b).trust, JudgeDepth(b, a).trust);
      EXPECT_EQ(JudgeDepth(a, b).reason, JudgeDepth(b, a).reason);
    }
  }
}

}  // namespace
}  // namespace contactlaws
