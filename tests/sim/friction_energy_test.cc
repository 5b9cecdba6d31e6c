// Copyright contactlaws authors.
//
// The energy ledger with friction through impacts whose load changes while
// the contacts slide: a tilted box thrown sideways onto a floor lands on a
// corner, slides under a rising normal force, sticks, tips and lands again.
// A ball on a floor (friction_test) never tests this: its load is constant.
// The total (kinetic + potential + elastic, the stick springs included, +
// dissipated) must hold as it holds without friction.

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

constexpr double kDuration = 0.8;  // s: four corner impacts and the tipping between
// The frictionless run's ledger drifts by 8.0e-4 of the start's energy over
// this run (the trapezoid of the law's dissipated power at 1e-4 s, measured);
// friction must not add to it. Before the springs' stored energy was taken
// off the work friction does, coulomb gained 3.6% here.
constexpr double kLedgerTolerance = 1.2e-3;  // of the start's total energy
// LuGre's bristles settle within mu / sigma0 = 5 um of slip, less than a
// step's slip at a landing: the trapezoid of friction's power over the step
// misses more of that than of coulomb's spring, which takes k_t's stretch.
// Measured (the CLI's run of this scene): 2.3e-3 at 1e-4 s, 1.2e-4 at 3e-5
// s, 4.9e-6 at 1e-5 s (coulomb 4.0e-4, 4.2e-5, 5.4e-6).
constexpr double kLuGreLedgerTolerance = 3e-3;  // of the start's total energy
// The dissipated energy may fall back for a step: RK4's last stage evaluates
// the springs on the previous commit, which the step's commit clamps to a
// cap that fell meanwhile (the end of an impact); the total does not move.
// Measured: 1.1e-3 of the start's energy (2.8e-3 J).
constexpr double kDipTolerance = 2e-3;  // of the start's total energy

std::string ThrownBox(const std::string& friction) {
  return fmt::format(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="box" pos="0 0 0.2" euler="10 35 5"><freejoint/>
      <geom name="box" type="box" size="0.05 0.05 0.05" mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:box" data="geom1=box geom2=floor law=hunt-crossley
    restitution=0.5 stiffness=1e7 friction={} mu=0.5"/></custom>
</mujoco>)",
                     friction);
}

class FrictionEnergyTest : public testing::MujocoTest,
                           public ::testing::WithParamInterface<const char*> {};

TEST_P(FrictionEnergyTest, TheTotalHoldsThroughImpactsThatSlideAndStick) {
  Simulation& sim = MakeSimulation(ThrownBox(GetParam()));
  sim.data()->qvel[0] = 1.0;  // m/s, sideways: each landing slides first
  sim.data()->qvel[4] = 5.0;  // rad/s
  sim.Step();  // the ledger reads the contacts' evaluations: none before a step
  const double start = sim.Energy().total();
  double worst = 0;
  double dissipated = 0;
  while (sim.time() < kDuration) {
    sim.Step();
    ASSERT_FALSE(sim.contacts().divergence()) << "t = " << sim.time();
    const EnergyLedger e = sim.Energy();
    worst = std::max(worst, std::abs(e.total() - start) / start);
    // what is lost stays lost
    EXPECT_GE(e.dissipated, dissipated - kDipTolerance * start) << "t = " << sim.time();
    dissipated = e.dissipated;
  }
  EXPECT_LT(worst, std::string(GetParam()) == "lugre" ? kLuGreLedgerTolerance : kLedgerTolerance);
  EXPECT_GT(dissipated, 0.25 * start);  // the impacts did lose energy: the test saw them
}

INSTANTIATE_TEST_SUITE_P(Models, FrictionEnergyTest,
                         ::testing::Values("none", "coulomb", "stribeck", "lugre"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

}  // namespace
}  // namespace contactlaws
