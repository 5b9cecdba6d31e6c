// Copyright contactlaws authors.
//
// The kinematics of the hooks: forces applied along the dof chain, driven
// bodies exact at any time.

#include "mujoco/kinematics.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <random>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class KinematicsTest : public testing::MujocoTest {};

TEST_F(KinematicsTest, AddPointForceIsMujocosApplyFTAlongTheChain) {
  // a tree: free base, hinge and slide children, a ball joint, a welded
  // child (no dofs of its own) and a static body
  UniqueModel m = Load(R"(<mujoco>
  <worldbody>
    <body name="static" pos="0 0 -1"><geom type="box" size="0.1 0.1 0.1"/></body>
    <body name="base" pos="0 0 1"><freejoint/><geom type="box" size="0.2 0.1 0.1" mass="2"/>
      <body name="arm" pos="0.3 0 0"><joint type="hinge" axis="0 1 0"/>
        <geom type="capsule" size="0.05 0.2" mass="1"/>
        <body name="slider" pos="0 0 0.3"><joint type="slide" axis="1 0 0"/>
          <geom type="sphere" size="0.05" mass="0.5"/>
          <body name="welded" pos="0.1 0 0"><geom type="sphere" size="0.03" mass="0.2"/></body>
        </body>
      </body>
      <body name="wrist" pos="-0.3 0 0"><joint type="ball"/>
        <geom type="sphere" size="0.05" mass="0.3"/></body>
    </body>
  </worldbody>
</mujoco>)");
  mjData* d = MakeData(m.get());
  for (int i = 0; i < m->nq; ++i) d->qpos[i] += 0.1 * std::sin(3.0 * i + 1);
  mj_normalizeQuat(m.get(), d->qpos);
  mj_forward(m.get(), d);
  std::vector<mjtNum> ours(m->nv), theirs(m->nv);
  const mjtNum force[3] = {1.5, -2.0, 0.7};
  const mjtNum zero[3] = {0, 0, 0};
  for (int b = 0; b < m->nbody; ++b) {
    const mjtNum point[3] = {0.2 * b, -0.1, 0.3};
    std::fill(ours.begin(), ours.end(), 0.5);
    std::fill(theirs.begin(), theirs.end(), 0.5);
    AddPointForce(m.get(), d, b, point, force, ours.data());
    mj_applyFT(m.get(), d, force, zero, point, b, theirs.data());
    for (int j = 0; j < m->nv; ++j) {
      // the same sums in another order: rounding only
      EXPECT_NEAR(ours[j], theirs[j], 1e-12) << "body " << b << " dof " << j;
    }
  }
}

TEST_F(KinematicsTest, PointJacobianRateGivesMujocosAccelerationAtRestingJoints) {
  // the oracle: MuJoCo's classical acceleration of a site
  // (mj_objectAcceleration after mj_rnePostConstraint) with q'' = 0 and no
  // gravity, at spinning joints of every kind along a tree
  UniqueModel m = Load(R"(<mujoco>
  <option gravity="0 0 0"/>
  <worldbody>
    <body name="base" pos="0 0 1" euler="10 20 30"><freejoint/>
      <geom type="box" size="0.2 0.1 0.1" mass="2"/>
      <site name="corner" pos="0.2 -0.1 0.1"/>
      <body name="arm" pos="0.3 0 0"><joint type="hinge" axis="0 1 0"/>
        <geom type="capsule" size="0.05 0.2" mass="1"/>
        <body name="slider" pos="0 0 0.3"><joint type="slide" axis="1 0 0"/>
          <geom type="sphere" size="0.05" mass="0.5"/>
          <site name="tip" pos="0.05 0.02 -0.01"/>
        </body>
      </body>
      <body name="wrist" pos="-0.3 0 0"><joint type="ball"/>
        <geom type="sphere" size="0.05" mass="0.3"/>
        <site name="rim" pos="0 0.05 0"/></body>
    </body>
  </worldbody>
</mujoco>)");
  mjData* d = MakeData(m.get());
  const double qvel[] = {0.3, -0.2, 0.5, 7, -4, 9, 11, -0.8, 6, -5, 3};
  ASSERT_EQ(m->nv, static_cast<int>(std::size(qvel)));
  std::copy(std::begin(qvel), std::end(qvel), d->qvel);
  mj_forward(m.get(), d);
  mju_zero(d->qacc, m->nv);
  mj_rnePostConstraint(m.get(), d);
  for (const char* name : {"corner", "tip", "rim"}) {
    const int site = mj_name2id(m.get(), mjOBJ_SITE, name);
    mjtNum expected[6];
    mj_objectAcceleration(m.get(), d, mjOBJ_SITE, site, expected, 0);
    for (int i = 0; i < 3; ++i) {
      mjtNum axis[3] = {0, 0, 0};
      axis[i] = 1;
      std::vector<mjtNum> row(m->nv, 0.0);
      AddPointJacobianRate(m.get(), d, m->site_bodyid[site], d->site_xpos + 3 * site, axis,
                           row.data());
      // rounding of sums of terms up to |w|^2 r ~ 100 m/s^2
      EXPECT_NEAR(mju_dot(row.data(), d->qvel, m->nv), expected[3 + i], 1e-12)
          << name << " " << i;
    }
  }
}

// The height above z = 0 of geom g's lowest point at d's state: a
// cylinder's lowest rim point, a capsule's or a sphere's lowest surface
// point, a box's vertex (vertex: 0-7, its corner's signs; -1: the lowest).
double LowestHeight(const mjModel* m, const mjData* d, int g, int vertex = -1) {
  const mjtNum* xpos = d->geom_xpos + 3 * g;
  const mjtNum* xmat = d->geom_xmat + 9 * g;
  const mjtNum* size = m->geom_size + 3 * g;
  const double az = xmat[8];  // the axis's z
  double lowest = std::numeric_limits<double>::infinity();
  switch (m->geom_type[g]) {
    case mjGEOM_SPHERE:
      return xpos[2] - size[0];
    case mjGEOM_CAPSULE:
      return xpos[2] - size[1] * std::abs(az) - size[0];
    case mjGEOM_CYLINDER:
      return xpos[2] - size[1] * std::abs(az) - size[0] * std::sqrt(1 - az * az);
    case mjGEOM_ELLIPSOID: {
      // the support distance along -z: |A R^T z|
      double q2 = 0;
      for (int j = 0; j < 3; ++j) q2 += size[j] * size[j] * xmat[6 + j] * xmat[6 + j];
      return xpos[2] - std::sqrt(q2);
    }
    default:  // a box: its eight vertices
      for (int k = 0; k < 8; ++k) {
        if (vertex >= 0 && k != vertex) continue;
        double z = xpos[2];
        for (int j = 0; j < 3; ++j) z += ((k >> j) & 1 ? 1 : -1) * size[j] * xmat[6 + j];
        lowest = std::min(lowest, z);
      }
      return lowest;
  }
}

TEST_F(KinematicsTest, TheDepthsJacobianRateIsItsSecondDerivativeAlongTheMotion) {
  // a free body above the floor, tilted and moving at a constant qvel: the
  // depth of its lowest point (direction -z) has d''(t) = row . qvel at q''
  // = 0, the row AddDepthJacobianRate's, against the central second
  // difference of LowestHeight over q(t) = q + qvel t (MuJoCo's
  // mj_integratePos: exact for a free body). At a rolling contact the
  // material point's centripetal acceleration is not the depth's: a
  // cylinder on its rim, spinning about its axis, keeps its rim's lowest
  // point where it is, and an ellipsoid's lowest point rolls over its
  // surface. The second difference at 1e-5 s is off by dt^2 / 12
  // times the fourth derivative (w^4 r: 1e-5 m/s^2 at 70 rad/s) and by the
  // heights' roundoff over dt^2 (1e-6 m/s^2 at 0.1 m).
  constexpr double kDt = 1e-5;          // s
  constexpr double kTolerance = 1e-4;   // m/s^2
  const char* geoms[] = {R"(type="cylinder" size="0.03 0.01")", R"(type="capsule" size="0.02 0.06")",
                         R"(type="sphere" size="0.03")", R"(type="box" size="0.03 0.04 0.05")",
                         R"(type="ellipsoid" size="0.05 0.03 0.02")"};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (const char* geom : geoms) {
    UniqueModel m = Load(fmt::format(R"(<mujoco>
  <worldbody><body name="body" pos="0 0 0.1"><freejoint/><geom {}/></body></worldbody>
</mujoco>)", geom));
    mjData* d = MakeData(m.get());
    for (int trial = 0; trial < 5; ++trial) {
      // an orientation whose axis is 15 to 75 degrees from the vertical
      // (neither flat on a face nor on its side), and a velocity
      const double tilt = (15 + 15 * trial) * M_PI / 180;
      const double quat[4] = {std::cos(tilt / 2), std::sin(tilt / 2) * std::cos(trial),
                              std::sin(tilt / 2) * std::sin(trial), 0};
      std::vector<mjtNum> q0(m->nq), v(m->nv);
      q0[2] = 0.1;
      for (int k = 0; k < 4; ++k) q0[3 + k] = quat[k];
      mju_normalize4(q0.data() + 3);
      for (int k = 0; k < 6; ++k) v[k] = (k < 3 ? 1.0 : 40.0) * uniform(random);
      // a box's lowest vertex at q0, followed
      int vertex = -1;
      mju_copy(d->qpos, q0.data(), m->nq);
      mj_kinematics(m.get(), d);
      for (int k = 0; m->geom_type[0] == mjGEOM_BOX && k < 8; ++k) {
        if (vertex < 0 || LowestHeight(m.get(), d, 0, k) < LowestHeight(m.get(), d, 0, vertex)) {
          vertex = k;
        }
      }
      const auto height = [&](double t) {
        mju_copy(d->qpos, q0.data(), m->nq);
        mj_integratePos(m.get(), d->qpos, v.data(), t);
        mj_kinematics(m.get(), d);
        return LowestHeight(m.get(), d, 0, vertex);
      };
      const double second = (height(kDt) - 2 * height(0) + height(-kDt)) / (kDt * kDt);
      // the row at q0: the lowest point's position, the depth along -z
      mju_copy(d->qpos, q0.data(), m->nq);
      mju_copy(d->qvel, v.data(), m->nv);
      mj_forward(m.get(), d);
      const double z = LowestHeight(m.get(), d, 0);
      // the lowest point itself (the contact point a narrowphase gives on a
      // floor), by the geometry LowestHeight reads
      double pos[3];
      const mjtNum* xpos = d->geom_xpos;
      const mjtNum* xmat = d->geom_xmat;
      const mjtNum* size = m->geom_size;
      const double axis[3] = {xmat[2], xmat[5], xmat[8]};
      const double sign = axis[2] > 0 ? -1 : 1;  // toward the lower end
      switch (m->geom_type[0]) {
        case mjGEOM_CYLINDER: {
          // the lower rim's centre, and its radius toward -z in its plane
          double u[3] = {-axis[2] * axis[0], -axis[2] * axis[1], -(1 - axis[2] * axis[2])};
          mju_normalize3(u);
          for (int k = 0; k < 3; ++k) pos[k] = xpos[k] + sign * size[1] * axis[k] + size[0] * u[k];
          break;
        }
        case mjGEOM_CAPSULE:
          for (int k = 0; k < 3; ++k) pos[k] = xpos[k] + sign * size[1] * axis[k];
          pos[2] -= size[0];
          break;
        case mjGEOM_SPHERE:
          mju_copy3(pos, xpos);
          pos[2] -= size[0];
          break;
        case mjGEOM_ELLIPSOID: {
          // R A^2 u / |A u|, u = R^T (-z)
          double u[3], s[3], q2 = 0;
          for (int j = 0; j < 3; ++j) {
            u[j] = -xmat[6 + j];
            q2 += size[j] * size[j] * u[j] * u[j];
          }
          for (int j = 0; j < 3; ++j) s[j] = size[j] * size[j] * u[j] / std::sqrt(q2);
          mju_mulMatVec(pos, xmat, s, 3, 3);
          mju_addTo3(pos, xpos);
          break;
        }
        default:  // the box's lowest vertex, found above
          mju_copy3(pos, xpos);
          for (int j = 0; j < 3; ++j) {
            for (int c = 0; c < 3; ++c) {
              pos[c] += ((vertex >> j) & 1 ? 1 : -1) * size[j] * xmat[3 * c + j];
            }
          }
      }
      ASSERT_NEAR(pos[2], z, 1e-12) << geom << ": the lowest point";
      std::vector<mjtNum> row(m->nv, 0.0);
      const double direction[3] = {0, 0, -1};
      AddDepthJacobianRate(m.get(), d, 1, 0, pos, direction, row.data());
      const double rate = mju_dot(row.data(), v.data(), m->nv);
      EXPECT_NEAR(rate, -second, kTolerance) << geom << ", tilt " << tilt;
    }
  }
}

TEST_F(KinematicsTest, DrivenBodyIsExactAtAnyTime) {
  // the passive hook places the table from d->time alone, whatever
  // mocap_pos holds: so at every RK4 stage
  UniqueModel m = LoadModelFile(std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/ball_table.xml");
  ContactModel cm(m.get(), "ball_table.xml");
  mjData* d = MakeData(m.get());
  ContactData contacts(cm, d);
  const int table = mj_name2id(m.get(), mjOBJ_BODY, "table");
  const int geom = mj_name2id(m.get(), mjOBJ_GEOM, "table");
  for (double t : {0.0, 0.1234, 0.5, 2.0}) {
    d->time = t;
    mj_forward(m.get(), d);
    const double z = 0.5 + 0.1 * std::sin(7.5 * t);
    EXPECT_NEAR(d->xpos[3 * table + 2], z, 1e-15) << "t = " << t;
    EXPECT_NEAR(d->geom_xpos[3 * geom + 2], z - 0.05, 1e-15) << "t = " << t;
    mjtNum vel[3];
    contacts.PointVelocity(table, d->xpos + 3 * table, vel);
    EXPECT_NEAR(vel[2], 0.75 * std::cos(7.5 * t), 1e-15);
  }
}

TEST_F(KinematicsTest, BoundingGapIsTheBroadphasesSpheresOrAPlane) {
  // a tilted plane, two spheres (rbound = radius), and a second plane
  UniqueModel m = Load(R"(<mujoco>
  <compiler angle="radian"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1" euler="0.3 0 0"/>
    <geom name="wall" type="plane" size="5 5 0.1" pos="9 0 0" euler="0 1.5 0"/>
    <body pos="0 0 1"><freejoint/><geom name="a" type="sphere" size="0.1"/></body>
    <body pos="0.3 0.4 1"><freejoint/><geom name="b" type="sphere" size="0.2"/></body>
  </worldbody>
</mujoco>)");
  mjData* d = MakeData(m.get());
  mj_forward(m.get(), d);
  const int floor = mj_name2id(m.get(), mjOBJ_GEOM, "floor");
  const int wall = mj_name2id(m.get(), mjOBJ_GEOM, "wall");
  const int a = mj_name2id(m.get(), mjOBJ_GEOM, "a");
  const int b = mj_name2id(m.get(), mjOBJ_GEOM, "b");
  // rounding of a few operations on numbers of order 1
  constexpr double kRounding = 1e-15;
  double gap = 0;
  mjtNum normal[3];

  // spheres: centre distance 0.5 less the radii, along the centres
  ASSERT_TRUE(BoundingGap(m.get(), d, a, b, &gap, normal));
  EXPECT_NEAR(gap, 0.5 - 0.1 - 0.2, kRounding);
  EXPECT_NEAR(normal[0], 0.6, kRounding);
  EXPECT_NEAR(normal[1], 0.8, kRounding);
  EXPECT_NEAR(normal[2], 0.0, kRounding);
  EXPECT_TRUE(FarApart(m.get(), d, a, b));

  // a plane tilted by 0.3 rad about x: its normal (0, -sin, cos); the
  // sphere's centre at height cos(0.3) over it, less its radius; the same
  // gap either way round, the normal reversed
  const double up[3] = {0, -std::sin(0.3), std::cos(0.3)};
  for (const bool plane_first : {true, false}) {
    const int g0 = plane_first ? floor : a;
    const int g1 = plane_first ? a : floor;
    ASSERT_TRUE(BoundingGap(m.get(), d, g0, g1, &gap, normal));
    EXPECT_NEAR(gap, std::cos(0.3) - 0.1, kRounding);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(normal[i], plane_first ? up[i] : -up[i], kRounding);
    EXPECT_TRUE(FarApart(m.get(), d, g0, g1));
  }

  // moved into reach: overlapping, not apart
  d->qpos[2] = 0.05;
  mj_forward(m.get(), d);
  ASSERT_TRUE(BoundingGap(m.get(), d, floor, a, &gap, normal));
  EXPECT_LT(gap, 0);
  EXPECT_FALSE(FarApart(m.get(), d, a, floor));

  // two planes have no bounding sphere: always near
  EXPECT_FALSE(BoundingGap(m.get(), d, floor, wall, &gap, normal));
  EXPECT_FALSE(FarApart(m.get(), d, floor, wall));
}

TEST_F(KinematicsTest, FreeBodyKinematicsIsMujocosPipelineForFreeBodies) {
  // free bodies whose inertial frames are off their frames (an off-centre
  // geom, a tilted capsule, two geoms), among static bodies
  UniqueModel m = Load(R"(<mujoco>
  <worldbody>
    <geom type="plane" size="1 1 0.1"/>
    <body name="static" pos="0 0 -1"><geom type="box" size="0.1 0.1 0.1"/></body>
    <body name="ball" pos="0 0 1"><freejoint/><geom type="sphere" size="0.05" mass="0.4"/></body>
    <body name="offset" pos="0.5 0 1" euler="10 20 30"><freejoint/>
      <geom type="box" pos="0.1 -0.05 0.02" size="0.2 0.1 0.05" mass="2"/></body>
    <body name="pair" pos="-0.5 0 1"><freejoint/>
      <geom type="capsule" fromto="0 0 0 0.2 0.1 0.3" size="0.03" mass="0.7"/>
      <geom type="sphere" pos="-0.1 0 0" size="0.04" mass="0.3"/></body>
  </worldbody>
</mujoco>)");
  ASSERT_TRUE(OnlySingleFreeBodies(m.get()));
  mjData* mujoco = MakeData(m.get());
  mjData* ours = MakeData(m.get());
  for (int i = 0; i < m->nq; ++i) mujoco->qpos[i] += 0.3 * std::sin(2.0 * i + 1);
  for (int i = 0; i < m->nv; ++i) mujoco->qvel[i] = 2.0 * std::cos(1.3 * i + 0.5);
  mj_normalizeQuat(m.get(), mujoco->qpos);
  // a quaternion off unit length, as interpolation leaves one before its
  // normalization
  mujoco->qpos[m->jnt_qposadr[1] + 3] *= 1.001;
  std::copy(mujoco->qpos, mujoco->qpos + m->nq, ours->qpos);
  std::copy(mujoco->qvel, mujoco->qvel + m->nv, ours->qvel);
  mj_kinematics(m.get(), mujoco);
  mj_comPos(m.get(), mujoco);
  mj_comVel(m.get(), mujoco);
  mj_crb(m.get(), mujoco);
  const double kinetic = FreeBodyKinematics(m.get(), ours);
  std::vector<mjtNum> mv(m->nv);
  mj_mulM(m.get(), mujoco, mv.data(), mujoco->qvel);
  const double mujoco_kinetic = 0.5 * mju_dot(mujoco->qvel, mv.data(), m->nv);
  // the same calls: the same bits
  for (int i = 0; i < m->nq; ++i) EXPECT_EQ(ours->qpos[i], mujoco->qpos[i]);
  for (int b = 1; b < m->nbody; ++b) {
    if (!SingleFreeBody(m.get(), b)) continue;
    for (int i = 0; i < 3; ++i) EXPECT_EQ(ours->xpos[3 * b + i], mujoco->xpos[3 * b + i]);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(ours->xquat[4 * b + i], mujoco->xquat[4 * b + i]);
    for (int i = 0; i < 9; ++i) {
      EXPECT_EQ(ours->xmat[9 * b + i], mujoco->xmat[9 * b + i]);
      EXPECT_EQ(ours->ximat[9 * b + i], mujoco->ximat[9 * b + i]);
    }
    for (int i = 0; i < 3; ++i) EXPECT_EQ(ours->xipos[3 * b + i], mujoco->xipos[3 * b + i]);
    // the same quantities summed in another order: rounding of values of
    // order 1 (positions of 1 m, velocities of 2 m/s and rad/s)
    constexpr double kRounding = 1e-14;
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(ours->subtree_com[3 * b + i], mujoco->subtree_com[3 * b + i], kRounding);
    }
    for (int i = 0; i < 6; ++i) {
      EXPECT_NEAR(ours->cvel[6 * b + i], mujoco->cvel[6 * b + i], kRounding) << "body " << b;
    }
  }
  ASSERT_GT(mujoco_kinetic, 1.0);
  EXPECT_NEAR(kinetic, mujoco_kinetic, 1e-14 * mujoco_kinetic);
}

TEST(NormalizeQuaternionTest, GivesMujocosBits) {
  // quaternions of every direction and of lengths from 1e-8 to 1e8, ones a
  // rounding off unit length (a third), and below mjMINVAL
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> exponent(-8, 8);
  for (int i = 0; i < 300000; ++i) {
    mjtNum q[4];
    for (mjtNum& c : q) c = normal(random);
    const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    const double scale = i % 3 == 0 ? 1 / length : std::pow(10.0, exponent(random));
    for (mjtNum& c : q) c *= i % 1000 == 1 ? 1e-17 : scale;
    mjtNum mujoco[4] = {q[0], q[1], q[2], q[3]};
    mjtNum ours[4] = {q[0], q[1], q[2], q[3]};
    mju_normalize4(mujoco);
    NormalizeQuaternion(ours);
    for (int k = 0; k < 4; ++k) {
      ASSERT_EQ(ours[k], mujoco[k]) << fmt::format("{} {} {} {}", q[0], q[1], q[2], q[3]);
    }
  }
}

TEST_F(KinematicsTest, OnlySingleFreeBodiesRefusesTreesAndDrivenBodies) {
  UniqueModel tree = Load(R"(<mujoco><worldbody>
    <body><freejoint/><geom type="sphere" size="0.1"/>
      <body pos="0.2 0 0"><geom type="sphere" size="0.1"/></body></body>
  </worldbody></mujoco>)");
  EXPECT_FALSE(OnlySingleFreeBodies(tree.get()));
  UniqueModel hinge = Load(R"(<mujoco><worldbody>
    <body><joint type="hinge"/><geom type="sphere" size="0.1"/></body>
  </worldbody></mujoco>)");
  EXPECT_FALSE(OnlySingleFreeBodies(hinge.get()));
  UniqueModel driven = Load(R"(<mujoco><worldbody>
    <body mocap="true"><geom type="sphere" size="0.1"/></body>
    <body pos="1 0 0"><freejoint/><geom type="sphere" size="0.1"/></body>
  </worldbody></mujoco>)");
  EXPECT_FALSE(OnlySingleFreeBodies(driven.get()));
  UniqueModel balls = Load(R"(<mujoco><worldbody>
    <body><geom type="box" size="0.1 0.1 0.1"/></body>
    <body pos="1 0 0"><freejoint/><geom type="sphere" size="0.1"/></body>
  </worldbody></mujoco>)");
  EXPECT_TRUE(OnlySingleFreeBodies(balls.get()));
}

}  // namespace
}  // namespace contactlaws
