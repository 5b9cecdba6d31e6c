// Copyright contactlaws authors.
//
// The narrowphase a geom pair gets (NarrowphaseOf), in either order, and the
// order mjCOLLISIONFUNC takes the geoms in; MaxContacts follows the same
// dispatch.

#include "scene/model_queries.h"

#include <gtest/gtest.h>

#include "geometry/box_box.h"
#include "geometry/polytope.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class ModelQueriesTest : public testing::MujocoTest {};

TEST_F(ModelQueriesTest, EachPairOfTypesHasOneNarrowphase) {
  UniqueModel m = Load(R"(<mujoco>
  <asset><mesh name="tetra" vertex="0 0 0  0.1 0 0  0 0.1 0  0 0 0.1"/></asset>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <geom name="wall" type="plane" size="5 5 0.1" pos="3 0 0" euler="0 1.5 0"/>
    <body pos="0 0 1"><freejoint/><geom name="box1" type="box" size="0.1 0.1 0.1"/></body>
    <body pos="1 0 1"><freejoint/><geom name="box2" type="box" size="0.1 0.1 0.1"/></body>
    <body pos="2 0 1"><freejoint/><geom name="tetra" type="mesh" mesh="tetra"/></body>
    <body pos="0 2 1"><freejoint/><geom name="ball" type="sphere" size="0.1"/></body>
  </worldbody>
</mujoco>)");
  auto id = [&](const char* name) { return mj_name2id(m.get(), mjOBJ_GEOM, name); };
  const int floor = id("floor"), wall = id("wall"), box1 = id("box1"), box2 = id("box2");
  const int tetra = id("tetra"), ball = id("ball");
  ASSERT_TRUE(IsPolytope(m.get(), tetra));
  struct Case {
    int g1, g2;
    Narrowphase expected;
    int max_contacts;
  };
  const Case cases[] = {
      {box1, box2, Narrowphase::kBoxBox, kMaxBoxBoxPoints},
      {box1, tetra, Narrowphase::kPolytope, kMaxPolytopePoints},
      {tetra, tetra, Narrowphase::kPolytope, kMaxPolytopePoints},
      {floor, box1, Narrowphase::kMujoco, mjMAXCONPAIR},
      {ball, tetra, Narrowphase::kMujoco, 1},
      {floor, ball, Narrowphase::kMujoco, 1},
      // MuJoCo 2.2.2 has no plane-plane function
      {floor, wall, Narrowphase::kNone, mjMAXCONPAIR},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(NarrowphaseOf(m.get(), c.g1, c.g2), c.expected) << c.g1 << " " << c.g2;
    EXPECT_EQ(NarrowphaseOf(m.get(), c.g2, c.g1), c.expected) << c.g2 << " " << c.g1;
    EXPECT_EQ(MaxContacts(m.get(), c.g1, c.g2), c.max_contacts) << c.g1 << " " << c.g2;
  }
}

TEST_F(ModelQueriesTest, CollisionOrderPutsTheLowerGeomTypeFirst) {
  UniqueModel m = Load(R"(<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body pos="0 0 1"><freejoint/><geom name="box" type="box" size="0.1 0.1 0.1"/></body>
    <body pos="1 0 1"><freejoint/><geom name="ball" type="sphere" size="0.1"/></body>
  </worldbody>
</mujoco>)");
  const int floor = 0, box = 1, ball = 2;
  ASSERT_EQ(m->geom_type[box], mjGEOM_BOX);
  EXPECT_EQ(CollisionOrder(m.get(), box, floor), (std::array<int, 2>{floor, box}));
  EXPECT_EQ(CollisionOrder(m.get(), floor, box), (std::array<int, 2>{floor, box}));
  EXPECT_EQ(CollisionOrder(m.get(), box, ball), (std::array<int, 2>{ball, box}));
  EXPECT_EQ(CollisionOrder(m.get(), ball, ball), (std::array<int, 2>{ball, ball}));
}

}  // namespace
}  // namespace contactlaws
