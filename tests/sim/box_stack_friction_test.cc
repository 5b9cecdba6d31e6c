// Copyright contactlaws authors.
//
// A stack of three cubes, each offset by 15% of its size on the one below,
// with Coulomb friction on every interface: frictionless it leans and slides
// off (box_stack_test); with friction it settles on its compliant contacts
// and then stands, the top cube still to the nanometre.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

constexpr double kHalf = 0.05;      // cube half size, m
constexpr double kOffset = 0.015;   // each cube on the one below, m (15% of the size)
constexpr double kSettle = 3.0;     // s: the lean is set by 0.5 s, its tail (1e-8 m) by 2 s, a
// last shift of 1.2e-9 m by 3 s (the points where the top cube's edges cross the
// side of the one below push along their depths' gradients: geometry/patch.h)
constexpr double kDuration = 10.0;  // s
// The lean the compliant contacts give an eccentric load: a depth difference
// of the order of the rest depth (mg/(4K))^(2/3) ~ 1e-4 m across the 0.1 m
// face tilts the stack by ~1e-3 rad, 1.5e-4 m at the top cube's height
// (measured 1.42e-4 m).
constexpr double kSettleBound = 3e-4;  // m
// After settling nothing moves: stick holds without creep.
constexpr double kStillBound = 1e-9;  // m

std::string OffsetStackXml() {
  std::string bodies, tags;
  for (int i = 0; i < 3; ++i) {
    bodies += fmt::format(R"(<body name="c{0}" pos="{1} 0 {2}"><freejoint/>
      <geom name="c{0}" type="box" size="{3} {3} {3}" mass="1"/></body>)",
                          i, i * kOffset, kHalf * (2 * i + 1), kHalf);
    tags += fmt::format(R"(<text name="contactlaw:t{}" data="geom1={} geom2=c{} law=hunt-crossley
      restitution=0.5 stiffness=1e7 min_impact_velocity=0.01 friction=coulomb mu=0.5"/>)",
                        i, i == 0 ? std::string("floor") : fmt::format("c{}", i - 1), i);
  }
  return fmt::format(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody><geom name="floor" type="plane" size="1 1 0.1"/>{}</worldbody>
  <custom>{}</custom>
</mujoco>)",
                     bodies, tags);
}

class BoxStackFrictionTest : public testing::MujocoTest {};

TEST_F(BoxStackFrictionTest, AnOffsetStackStandsWithFriction) {
  Simulation& sim = MakeSimulation(OffsetStackXml());
  const int top = mj_name2id(sim.model(), mjOBJ_BODY, "c2");
  const double start = sim.data()->qpos[7 * 2];
  while (sim.time() < kSettle) sim.Step();
  const double settled = sim.data()->qpos[7 * 2];
  while (sim.time() < kDuration) {
    sim.Step();
    ASSERT_FALSE(sim.contacts().divergence()) << "t = " << sim.time();
  }
  EXPECT_LT(std::abs(settled - start), kSettleBound);
  EXPECT_LT(std::abs(sim.data()->qpos[7 * 2] - settled), kStillBound);
  EXPECT_GT(sim.data()->xpos[3 * top + 2], 4.9 * kHalf) << "the top cube is still on the stack";
}

}  // namespace
}  // namespace contactlaws
