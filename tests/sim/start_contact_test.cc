// Copyright contactlaws authors.
//
// StartContacts: the law's force, load and damper lag of the pairs in contact
// where a run starts, against closed forms; a block placed deep is a deep
// start, the same block at its static depth, a settled stack and touching
// bodies are not; the factor is the peak of a drop from touching.

#include "sim/start_contact.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

// testing::SlidingBlockXml's block
constexpr double kMass = 0.2;       // kg
constexpr double kStiffness = 1e7;  // K, N/m^1.5
constexpr double kExponent = 1.5;
constexpr double kGravity = 9.81;  // m/s^2
constexpr double kWeight = kMass * kGravity;
// The law at fixed depths, and Newton on a free body with no constraint:
// rounding alone.
constexpr double kRounding = 1e-9;  // relative
// The lag from DampingCoefficient's finite difference in d' (the law is
// linear in d' there: rounding over a step of 1e-3 v0).
constexpr double kLagTolerance = 1e-6;  // relative

// The lag at rest under the block's weight (check's "at rest").
double RestLag(const Simulation& sim) {
  return RestingDamperLag(sim.contact_model().pairs()[0].params, kWeight, kMass);
}

class StartContactTest : public testing::MujocoTest {};

TEST_F(StartContactTest, ABlockPlacedDeepIsADeepStartWithAShortLag) {
  const double depth = 1e-4;
  Simulation& sim = MakeSimulation(testing::SlidingBlockXml(depth));
  const std::vector<StartContact> starts = StartContacts(&sim);
  ASSERT_EQ(starts.size(), 1u);
  const StartContact& s = starts[0];
  EXPECT_EQ(s.points, 4);
  EXPECT_NEAR(s.depth, depth, kRounding * depth);
  const double force = 4 * kStiffness * std::pow(depth, kExponent);  // 40 N
  EXPECT_NEAR(s.force, force, kRounding * force);
  EXPECT_NEAR(s.load, kWeight, kRounding * kWeight);
  EXPECT_TRUE(s.deep);
  // c = a F / v0: the lag at the start is the one at rest x W / F (20.4x
  // shorter: 1.8e-6 s against 3.68e-5 s)
  EXPECT_NEAR(s.lag, RestLag(sim) * kWeight / force, kLagTolerance * s.lag);

  const std::vector<std::string> w = DeepStartWarnings(sim, starts, kCommandLineSpelling);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("contactlaw:block-floor (block, floor): starts 0.0001 m deep in contact: "
                       "its law pushes with 40 N against the 1.962 N that presses it (20.4 "
                       "times, beyond the 2.5 times of a body placed touching",
                       0),
            0u)
      << w[0];
  EXPECT_NE(w[0].find("--settle moves the bodies in contact"), std::string::npos) << w[0];
}

TEST_F(StartContactTest, TheBlockAtItsStaticDepthIsNot) {
  // 4 K d^n = W
  const double depth = std::pow(kWeight / (4 * kStiffness), 1 / kExponent);
  Simulation& sim = MakeSimulation(testing::SlidingBlockXml(depth));
  const std::vector<StartContact> starts = StartContacts(&sim);
  ASSERT_EQ(starts.size(), 1u);
  EXPECT_NEAR(starts[0].force, kWeight, kRounding * kWeight);
  EXPECT_NEAR(starts[0].load, kWeight, kRounding * kWeight);
  EXPECT_FALSE(starts[0].deep);
  EXPECT_NEAR(starts[0].lag, RestLag(sim), kLagTolerance * starts[0].lag);
  EXPECT_TRUE(DeepStartWarnings(sim, starts, kCommandLineSpelling).empty());
}

// Three 1 kg cubes stacked on a floor at d = 0 (settle_test's stack).
std::string Stack() {
  std::string bodies, tags;
  for (int i = 0; i < 3; ++i) {
    bodies += fmt::format(R"(<body name="c{0}" pos="0 0 {1}"><freejoint/>
      <geom name="c{0}" type="box" size="0.05 0.05 0.05" mass="1"/></body>)",
                          i, 0.05 * (2 * i + 1));
    tags += fmt::format(R"(<text name="contactlaw:t{0}" data="geom1={1} geom2=c{0}
      law=hunt-crossley restitution=0.5 stiffness=1e7 min_impact_velocity=1e-2"/>)",
                        i, i == 0 ? std::string("floor") : fmt::format("c{}", i - 1));
  }
  return fmt::format(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody><geom name="floor" type="plane" size="2 2 0.1"/>{}</worldbody>
  <custom>{}</custom>
</mujoco>)",
                     bodies, tags);
}

TEST_F(StartContactTest, ASettledStackIsNotAndEachPairCarriesWhatIsAboveIt) {
  SimulationOptions options;
  options.settle = true;
  Simulation& sim = MakeSimulation(Stack(), options);
  const std::vector<StartContact> starts = StartContacts(&sim);
  ASSERT_EQ(starts.size(), 3u);
  for (const StartContact& s : starts) {
    // pair t holds the 3 - t cubes above the floor or cube t - 1; settled
    // to kSettleResidual (1e-5 m/s^2 on <= 3 kg): 3e-5 N of <= 29 N
    const double above = (3 - sim.contact_model().pairs()[s.pair].tag) * kGravity;
    EXPECT_NEAR(s.load, above, 1e-5 * above);
    EXPECT_NEAR(s.force, above, 1e-5 * above);
    EXPECT_FALSE(s.deep);
  }
  EXPECT_TRUE(DeepStartWarnings(sim, starts, kCommandLineSpelling).empty());
}

TEST_F(StartContactTest, BodiesPlacedTouchingAreNoStartContact) {
  // the stack unsettled, and a cradle's touching balls without gravity
  EXPECT_TRUE(StartContacts(&MakeSimulation(Stack())).empty());
  const std::string cradle = R"(<mujoco><option gravity="0 0 0"/><worldbody>
    <body pos="0 0 1"><joint type="slide" axis="1 0 0"/>
      <geom name="a" type="sphere" size="0.05" mass="1" group="1"/></body>
    <body pos="0.1 0 1"><joint type="slide" axis="1 0 0"/>
      <geom name="b" type="sphere" size="0.05" mass="1" group="1"/></body></worldbody>
    <custom><text name="contactlaw:chain" data="geom1=group:1 geom2=group:1 law=hertz
      stiffness=1e7"/></custom></mujoco>)";
  EXPECT_TRUE(StartContacts(&MakeSimulation(cradle)).empty());
}

TEST_F(StartContactTest, TwoBallsOverlappingWithoutGravityHaveNoLoad) {
  Simulation& sim = MakeSimulation(R"(<mujoco><option gravity="0 0 0"/><worldbody>
    <body pos="0 0 1"><freejoint/><geom name="a" type="sphere" size="0.05" mass="1"/></body>
    <body pos="0.0999 0 1"><freejoint/><geom name="b" type="sphere" size="0.05" mass="1"/>
    </body></worldbody><custom><text name="contactlaw:ab" data="geom1=a geom2=b law=hertz
      stiffness=1e7"/></custom></mujoco>)");
  const std::vector<StartContact> starts = StartContacts(&sim);
  ASSERT_EQ(starts.size(), 1u);
  EXPECT_NEAR(starts[0].load, 0, kRounding * starts[0].force);
  EXPECT_TRUE(starts[0].deep);
  const std::vector<std::string> w = DeepStartWarnings(sim, starts, kCommandLineSpelling);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("(nothing presses it: at rest it would not touch)"), std::string::npos)
      << w[0];
}

TEST_F(StartContactTest, TheFactorIsThePeakForceOfADropFromTouching) {
  // a 1 kg ball placed touching (d = 0) and released under gravity, Hertz
  // (no damping): its force peaks at (n + 1) W, sampled every 1e-5 s step of
  // a ~16 ms oscillation (h omega ~ 4e-3: the sampled peak within 1e-5)
  Simulation& sim = MakeSimulation(
      testing::DropXml("law=hertz stiffness=1e7", 0.0, "RK4", 1e-5, true, 1.0, 0.1));
  double peak = 0;
  while (sim.time() < 0.02) {
    sim.Step();
    mj_forward(sim.model(), sim.data());
    peak = std::max(peak, sim.Readings()[0].force);
  }
  const double factor = DeepStartFactor(sim.contact_model().pairs()[0].params);
  EXPECT_EQ(factor, 2.5);
  EXPECT_NEAR(peak / kGravity, factor, 1e-4);
}

}  // namespace
}  // namespace contactlaws
