// Copyright contactlaws authors.
//
// AppendVisibleContacts: the tagged contact points listed in d->contact,
// outside the solver, drawn by mjv_updateScene as contact points, gone at the
// next collision pass, never beyond nconmax; none for motion-only steps.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "mujoco/visible_contacts.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class VisibleContactsTest : public testing::MujocoTest {
 protected:
  // The drop scene stepped until the ball is in contact (depth > kDeepEnough).
  Simulation& InContact() {
    Simulation& sim = MakeSimulation(
        testing::DropXml("law=hunt-crossley restitution=0.5 stiffness=1e7", 1.0));
    while (sim.contacts().latest().empty() || sim.contacts().latest()[0].depth < kDeepEnough) {
      sim.Step();
      if (sim.time() > kMaxTime) break;
    }
    return sim;
  }

  // Scene geoms MuJoCo drew as contact points (decor cylinders: 2.2.2 draws
  // a contact point as a cylinder of category mjCAT_DECOR, objtype unknown).
  static int ContactPointGeoms(const mjModel* m, mjData* d) {
    mjvScene scene;
    mjv_defaultScene(&scene);
    mjv_makeScene(m, &scene, kSceneGeoms);
    mjvOption option;
    mjv_defaultOption(&option);
    option.flags[mjVIS_CONTACTPOINT] = 1;
    mjvCamera camera;
    mjv_defaultCamera(&camera);
    mjv_updateScene(m, d, &option, nullptr, &camera, mjCAT_DECOR, &scene);
    int count = 0;
    for (int i = 0; i < scene.ngeom; ++i) {
      const mjvGeom& g = scene.geoms[i];
      if (g.category == mjCAT_DECOR && g.type == mjGEOM_CYLINDER) ++count;
    }
    mjv_freeScene(&scene);
    return count;
  }

  // a contact well established (the drop's maximum depth is about 1e-4 m)
  static constexpr double kDeepEnough = 1e-5;
  static constexpr double kMaxTime = 0.05;  // s: the ball touches within 0.1 ms
  static constexpr int kSceneGeoms = 100;
};

// Exact copies and unit vectors: nothing is computed but the tangents.
constexpr double kFrameTolerance = 1e-12;

TEST_F(VisibleContactsTest, AppendsEachTaggedPointOutsideTheSolver) {
  Simulation& sim = InContact();
  mjData* d = sim.data();
  ASSERT_EQ(sim.contacts().latest().size(), 1u);
  const PointEvaluation& point = sim.contacts().latest()[0];
  ASSERT_EQ(d->ncon, 1);  // the step listed it
  // a collision pass (mj_forward) lists MuJoCo's contacts anew: the filter
  // took the tagged pair from MuJoCo
  mj_forward(sim.model(), d);
  ASSERT_EQ(d->ncon, 0);
  VisibleContactsOverflow overflow;
  EXPECT_EQ(AppendVisibleContacts(sim.contacts(), sim.data(), &overflow), 1);
  ASSERT_EQ(d->ncon, 1);
  const mjContact& con = d->contact[0];
  EXPECT_EQ(con.exclude, 1);
  EXPECT_EQ(con.efc_address, -1);
  EXPECT_EQ(con.dim, 1);
  EXPECT_EQ(con.geom1, mj_name2id(sim.model(), mjOBJ_GEOM, "floor"));
  EXPECT_EQ(con.geom2, mj_name2id(sim.model(), mjOBJ_GEOM, "ball"));
  EXPECT_EQ(con.dist, -point.depth);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(con.pos[k], point.pos[k]);
  // the normal, then two tangents: an orthonormal right-handed frame
  EXPECT_NEAR(con.frame[2], 1.0, kFrameTolerance);  // floor to ball: up
  mjtNum cross[3];
  mju_cross(cross, con.frame + 3, con.frame + 6);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(cross[k], con.frame[k], kFrameTolerance);
  EXPECT_NEAR(mju_dot3(con.frame, con.frame + 3), 0.0, kFrameTolerance);
  EXPECT_EQ(overflow.dropped, 0);
}

TEST_F(VisibleContactsTest, MujocoDrawsThePointsAndTheNextCollisionClearsThem) {
  Simulation& sim = InContact();
  mjData* d = sim.data();
  EXPECT_EQ(ContactPointGeoms(sim.model(), d), 1) << "the step lists its points";
  mj_forward(sim.model(), d);  // mj_collision lists the contacts anew: ours are gone
  EXPECT_EQ(d->ncon, 0);
  EXPECT_EQ(ContactPointGeoms(sim.model(), d), 0);
  VisibleContactsOverflow overflow;
  AppendVisibleContacts(sim.contacts(), sim.data(), &overflow);
  EXPECT_EQ(ContactPointGeoms(sim.model(), d), 1);
}

TEST_F(VisibleContactsTest, NeverBeyondNconmaxCountsWhatDidNotFitAndWarnsOnce) {
  Simulation& sim = InContact();
  mjData* d = sim.data();
  d->ncon = sim.model()->nconmax;  // a full list
  VisibleContactsOverflow overflow;
  EXPECT_EQ(AppendVisibleContacts(sim.contacts(), sim.data(), &overflow), 0);
  EXPECT_EQ(AppendVisibleContacts(sim.contacts(), sim.data(), &overflow), 0);
  EXPECT_EQ(d->ncon, sim.model()->nconmax);
  EXPECT_EQ(overflow.dropped, 2);
  EXPECT_EQ(ExpectMujocoWarning("nconmax"), 1u);
  d->ncon = 0;
}

TEST_F(VisibleContactsTest, NothingOutOfContact) {
  Simulation& sim = MakeSimulation(
      testing::DropXml("law=hunt-crossley restitution=0.5 stiffness=1e7", 1.0, "Euler", 1e-5,
                       false, 1.0, 0.5));
  sim.Step();
  VisibleContactsOverflow overflow;
  EXPECT_EQ(AppendVisibleContacts(sim.contacts(), sim.data(), &overflow), 0);
  EXPECT_EQ(sim.data()->ncon, 0);
}

TEST_F(VisibleContactsTest, MotionOnlyStepsKeepTheMotionAndListOrPlaceNothingElse) {
  // the cube toss scene (a light, a box landing on a board), run through its
  // landing twice: the motion-only run (ContactData::KeepMotionOnly) lists
  // no points and places no light, and moves the same to the bit
  SimulationOptions motion_only;
  motion_only.motion_only = true;
  Simulation& full = MakeSceneSimulation("cube_toss.xml");
  Simulation& lean = MakeSceneSimulation("cube_toss.xml", motion_only);
  const int steps = 600;  // 0.41 s: the cube falls 0.15 m to the board in 0.17 s
  for (int k = 0; k < steps; ++k) {
    full.Step();
    lean.Step();
  }
  const mjModel* m = full.model();
  ASSERT_FALSE(full.contacts().latest().empty()) << "the cube is on the board";
  EXPECT_GT(full.data()->ncon, 0);
  EXPECT_EQ(lean.data()->ncon, 0);
  ASSERT_EQ(m->nlight, 1);
  EXPECT_EQ(full.data()->light_xpos[2], 2.0);  // <light pos="0 0 2"/>
  EXPECT_EQ(lean.data()->light_xpos[2], 0.0);  // never placed
  for (int i = 0; i < m->nq; ++i) EXPECT_EQ(lean.data()->qpos[i], full.data()->qpos[i]) << i;
  for (int i = 0; i < m->nv; ++i) EXPECT_EQ(lean.data()->qvel[i], full.data()->qvel[i]) << i;
}

}  // namespace
}  // namespace contactlaws
