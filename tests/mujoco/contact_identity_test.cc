// Copyright contactlaws authors.
//
// Contact identity: a point's memory belongs to the physical point, found by
// where it sits on the two bodies, whatever order MuJoCo's narrowphase lists
// the points in. A box and a cylinder land tilted, rock and tumble; every
// touch is held against the rigid-body state just before it, computed here
// from qpos and qvel alone.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

constexpr double kTimestep = 1e-4;  // s
constexpr double kGravity = 9.81;   // m/s^2
// The library's touch velocity is the approach rate at the step before the
// touch, taken with the touch's own configuration (its Jacobian at the
// contact point); the oracle takes the previous configuration's. They differ
// by one step's turn of the lever arm and of the contact point's own descent:
// |w|^2 r h + g h (the oracle's bound at each touch, TouchVelocityTolerance),
// with this margin for the point MuJoCo puts midway into the overlap.
constexpr double kTouchVelocityMargin = 1.5;

// A body point's height and vertical velocity at the state (qpos, qvel) of a
// free body whose joint starts at qpos[0] and qvel[0].
struct PointMotion {
  double z = 0;
  double vz = 0;
  double turn = 0;  // |w|^2 r: the acceleration of the point's rotation, m/s^2
};

PointMotion MotionOf(const mjData* d, const mjtNum local[3]) {
  mjtNum rotation[9], offset[3], spin[3], turn[3];
  mju_quat2Mat(rotation, d->qpos + 3);
  mju_rotVecMat(offset, local, rotation);
  // free joint: linear velocity in the world frame, angular in the body's
  mju_rotVecMat(spin, d->qvel + 3, rotation);
  mju_cross(turn, spin, offset);
  return {d->qpos[2] + offset[2], d->qvel[2] + turn[2],
          mju_dot3(spin, spin) * mju_norm3(offset)};
}

// A touch the oracle expects: a body point crossing the floor between two
// step starts, and its approach rate at the first of them.
struct Touch {
  double after = 0;      // s, the last step start above the floor
  double before = 0;     // s, the first below
  double speed = 0;      // m/s, -vz at `after`
  double tolerance = 0;  // m/s, how far the library's touch velocity may be
};

// Points of the body (body frame) watched at a state: fixed corners, or the
// lowest point of a round body, which moves over it.
using PointsAt = std::vector<std::array<mjtNum, 3>> (*)(const mjData* d);

// Every crossing of the floor by the watched points (the i-th of one state
// against the i-th of the next) while d is stepped by contacts until t_end.
std::vector<Touch> StepAndWatch(ContactData* contacts, mjData* d, PointsAt points_at,
                                double t_end) {
  std::vector<Touch> touches;
  auto motions = [&] {
    std::vector<PointMotion> motion;
    for (const std::array<mjtNum, 3>& p : points_at(d)) motion.push_back(MotionOf(d, p.data()));
    return motion;
  };
  std::vector<PointMotion> last = motions();
  double last_time = d->time;
  while (d->time < t_end) {
    contacts->Step();
    const std::vector<PointMotion> now = motions();
    for (size_t i = 0; i < now.size(); ++i) {
      if (last[i].z >= 0 && now[i].z < 0) {
        const double tolerance =
            kTouchVelocityMargin * (last[i].turn + kGravity) * (d->time - last_time);
        touches.push_back({last_time, d->time, -last[i].vz, tolerance});
      }
    }
    last = now;
    last_time = d->time;
  }
  return touches;
}

// Each touch has an impact of its own: opened within the touch's step (its
// extrapolated time_contact up to a step earlier), at the touch's speed.
void ExpectOneImpactPerTouch(const std::vector<Touch>& touches,
                             const std::vector<Episode>& impacts, const std::string& what) {
  EXPECT_EQ(impacts.size(), touches.size()) << what;
  std::vector<bool> used(impacts.size(), false);
  for (const Touch& touch : touches) {
    size_t k = 0;
    for (; k < impacts.size(); ++k) {
      const Episode& e = impacts[k];
      if (!used[k] && e.time_contact >= touch.after - kTimestep &&
          e.time_contact <= touch.before &&
          std::abs(e.impact_velocity - touch.speed) < touch.tolerance) {
        break;
      }
    }
    ASSERT_LT(k, impacts.size()) << what << ": no impact for the touch at t = " << touch.before
                                 << " s at " << touch.speed << " +- " << touch.tolerance
                                 << " m/s";
    used[k] = true;
  }
  for (const Episode& e : impacts) {
    if (!e.open) {
      EXPECT_LT(e.time_contact, e.time_separation) << what;
    }
  }
}

class ContactIdentityTest : public testing::MujocoTest {};

std::string BoxXml(std::string_view qvel) {
  return fmt::format(R"(<mujoco>
  <option timestep="{}" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="box" pos="0 0 0.2" quat="0.95 0.25 0.15 0.1">
      <freejoint/>
      <geom name="box" type="box" size="0.1 0.06 0.03" mass="1"/>
    </body>
  </worldbody>
  <keyframe><key qpos="0 0 0.2 0.95 0.25 0.15 0.1" qvel="{}"/></keyframe>
  <custom><text name="contactlaw:box-floor"
    data="geom1=box geom2=floor law=hunt-crossley restitution=0.5 stiffness=1e7"/></custom>
</mujoco>)",
                     kTimestep, qvel);
}

// Landing tilted, then bouncing and rocking on its corners (and, spun,
// tumbling): each corner's touch is an episode of its own, opened at the
// corner's approach rate, and no episode ever jumps to another corner.
TEST_F(ContactIdentityTest, EveryCornerOfATiltedBoxIsItsOwnPoint) {
  for (const char* qvel : {"0.3 0 -1 2 -3 1", "1 0.5 -2 15 -10 8"}) {
    UniqueModel m = Load(BoxXml(qvel));
    ContactModel cm(m.get(), "box.xml");
    mjData* d = MakeData(m.get());
    mj_resetDataKeyframe(m.get(), d, 0);
    ContactData contacts(cm, d);
    const PointsAt corners = [](const mjData*) {
      std::vector<std::array<mjtNum, 3>> points;
      for (const double x : {-0.1, 0.1}) {
        for (const double y : {-0.06, 0.06}) {
          for (const double z : {-0.03, 0.03}) points.push_back({x, y, z});
        }
      }
      return points;
    };
    const std::vector<Touch> touches = StepAndWatch(&contacts, d, corners, 1.5);
    ASSERT_GE(touches.size(), 4u) << qvel << ": the box must land and rock";
    ExpectOneImpactPerTouch(touches, contacts.point_episodes(), qvel);
  }
}

// A cylinder lands tilted and rocks on its rim, its contact point running
// along the rim: each impact of the pair opens at the approach rate of
// the cylinder's lowest point, and every point episode lies inside one.
// (What the point's identity itself must keep, the box's corners test.)
TEST_F(ContactIdentityTest, ACylinderRockingOnItsRimCollidesAtItsLowestPointsRate) {
  UniqueModel m = Load(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="can" pos="0 0 0.2" quat="0.96 0.28 0 0">
      <freejoint/>
      <geom name="can" type="cylinder" size="0.05 0.08" mass="1"/>
    </body>
  </worldbody>
  <keyframe><key qpos="0 0 0.2 0.96 0.28 0 0" qvel="0 0 -1 0 3 0"/></keyframe>
  <custom><text name="contactlaw:can-floor"
    data="geom1=can geom2=floor law=hunt-crossley restitution=0.5 stiffness=1e7"/></custom>
</mujoco>)");
  ContactModel cm(m.get(), "can.xml");
  mjData* d = MakeData(m.get());
  mj_resetDataKeyframe(m.get(), d, 0);
  ContactData contacts(cm, d);
  // the lowest point of the can (radius 0.05 m, half length 0.08 m) at the
  // state: on the rim of the lower end, below the axis
  const PointsAt lowest = [](const mjData* d) {
    mjtNum rotation[9], down[3];
    const mjtNum world_down[3] = {0, 0, -1};
    mju_quat2Mat(rotation, d->qpos + 3);
    mju_mulMatTVec(down, rotation, world_down, 3, 3);
    const double radial = std::hypot(down[0], down[1]);
    std::vector<std::array<mjtNum, 3>> point(1);
    if (radial > 0) point[0] = {0.05 * down[0] / radial, 0.05 * down[1] / radial, 0};
    point[0][2] = down[2] > 0 ? 0.08 : -0.08;
    return point;
  };
  const std::vector<Touch> touches = StepAndWatch(&contacts, d, lowest, 1.0);
  ASSERT_GE(touches.size(), 2u) << "the can must land and bounce";
  ExpectOneImpactPerTouch(touches, contacts.impacts(), "impacts");
  // the points of the can: each inside an impact of the pair
  for (const Episode& e : contacts.point_episodes()) {
    const bool inside = std::any_of(
        contacts.impacts().begin(), contacts.impacts().end(), [&](const Episode& c) {
          return e.time_contact >= c.time_contact - kTimestep &&
                 (c.open || e.time_contact <= c.time_separation + kTimestep);
        });
    EXPECT_TRUE(inside) << "a point episode at t = " << e.time_contact << " outside every impact";
  }
  std::printf("can: %zu impacts, %zu point episodes\n", contacts.impacts().size(),
              contacts.point_episodes().size());
}

}  // namespace
}  // namespace contactlaws
