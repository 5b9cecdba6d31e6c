// Copyright contactlaws authors.
//
// Touching chains: Newton's cradles of 3 and 5 balls, touching at rest, the
// first one sent into the others. The contacts between touching balls open
// at almost no approach speed and are then compressed by the pulse: their
// laws must not turn plastic (Episode::max_approach_velocity). Gravity is off
// and the balls slide on x alone, as in the closed forms.

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contactlaws/law.h"
#include "sim/run_report.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

constexpr double kRadius = 0.05;  // m
constexpr double kMass = 1.0;     // kg
constexpr double kSpeed = 1.0;    // m/s, the first ball's
// Equal and opposite forces at one point: the momentum changes by rounding
// alone, step after step.
constexpr double kMomentumTolerance = 1e-9;  // relative
// Hertz stores and gives back: RK4 at 1e-5 s against a 3.6 ms contact keeps
// the ledger's total to rounding and the method's h^4.
constexpr double kEnergyTolerance = 1e-6;  // relative

// balls in a row along x, touching, on slide joints; ball 0 at kSpeed
std::string CradleXml(int balls, const std::string& tag) {
  std::string bodies, qvel;
  for (int i = 0; i < balls; ++i) {
    bodies += fmt::format(R"(<body name="b{0}" pos="{1} 0 1"><joint name="x{0}" type="slide"
      axis="1 0 0"/><geom name="b{0}" type="sphere" size="{2}" mass="{3}" group="1"/></body>)",
                          i, 2 * kRadius * i, kRadius, kMass);
    qvel += i == 0 ? fmt::format("{}", kSpeed) : " 0";
  }
  return fmt::format(R"(<mujoco>
  <option timestep="1e-5" integrator="RK4" gravity="0 0 0"/>
  <worldbody>{}</worldbody>
  <keyframe><key qvel="{}"/></keyframe>
  <custom><text name="contactlaw:chain" data="geom1=group:1 geom2=group:1 {}"/></custom>
</mujoco>)",
                     bodies, qvel, tag);
}

struct Totals {
  double momentum = 0;  // kg m/s
  double kinetic = 0;   // J
};

Totals TotalsOf(const Simulation& sim) {
  Totals t;
  for (int j = 0; j < sim.model()->nv; ++j) {
    const double v = sim.data()->qvel[j];
    t.momentum += kMass * v;
    t.kinetic += 0.5 * kMass * v * v;
  }
  return t;
}

class CradleTest : public testing::MujocoTest {};

TEST_F(CradleTest, HertzKeepsMomentumAndEnergy) {
  for (const int balls : {3, 5}) {
    Simulation& sim = MakeSimulation(CradleXml(balls, "law=hertz stiffness=1e7"));
    const Totals before = TotalsOf(sim);
    while (sim.time() < 0.1) sim.Step();
    mj_forward(sim.model(), sim.data());
    const Totals after = TotalsOf(sim);
    EXPECT_NEAR(after.momentum, before.momentum, kMomentumTolerance * before.momentum) << balls;
    EXPECT_NEAR(sim.Energy().total(), before.kinetic, kEnergyTolerance * before.kinetic)
        << balls;
    // the pulse has left through the last ball
    EXPECT_GT(sim.data()->qvel[balls - 1], 0.9 * kSpeed) << balls;
  }
}

// Hunt-Crossley at e = 0.9: each contact, taken as an impact of two equal
// balls, loses (1 - e_post^2) / 2 of the energy it receives, e_post its exact
// rebound; the pulse crosses balls - 1 contacts: no more may be lost. With
// d'/v0 in the hundreds (v0 the touch speed of touching balls) it would lose
// nearly all. Every chained contact is named in one warning line.
TEST_F(CradleTest, ADissipativeLawKeepsMomentumAndLosesNoMoreThanItsRestitutionAllows) {
  const double e_post = ExactRebound(HysteresisCoefficient(*ParseLawName("hunt-crossley"), 0.9));
  for (const int balls : {3, 5}) {
    Simulation& sim =
        MakeSimulation(CradleXml(balls, "law=hunt-crossley restitution=0.9 stiffness=1e7"));
    const Totals before = TotalsOf(sim);
    while (sim.time() < 0.1) sim.Step();
    const Totals after = TotalsOf(sim);
    EXPECT_NEAR(after.momentum, before.momentum, kMomentumTolerance * before.momentum) << balls;
    const double lost = 1 - after.kinetic / before.kinetic;
    EXPECT_GT(lost, 0) << balls;
    EXPECT_LE(lost, (balls - 1) * (1 - e_post * e_post) / 2) << balls;
    std::printf("%d balls: %.4f of the energy lost (bound %.4f)\n", balls, lost,
                (balls - 1) * (1 - e_post * e_post) / 2);
    // the contacts between touching balls are chained (flagged): pushed on
    // from both sides, one may leave faster than it closed, as no impact can
    int chained = 0;
    for (const Episode& c : sim.contacts().impacts()) {
      if (c.open) continue;
      chained += c.chained();
      if (!c.chained()) {
        EXPECT_LE(c.restitution_post(), 1.0) << balls << " balls, pair " << c.pair;
      }
    }
    EXPECT_GE(chained, balls - 2) << balls;
    // one line for the tag's pairs, with their count
    const std::vector<std::string> warnings = ChainedContactWarnings(sim, kCommandLineSpelling);
    ASSERT_EQ(warnings.size(), 1u) << balls;
    if (chained > 1) {
      EXPECT_NE(warnings[0].find(fmt::format("and {} more pair", chained - 1)),
                std::string::npos)
          << warnings[0];
    }
    EXPECT_NE(warnings[0].find("contactlaw:chain (b"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("touched at"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("a pulse through touching bodies"), std::string::npos)
        << warnings[0];
  }
}

// Balls placed exactly touching (2 cm, centres 4 cm apart from x = 0) and
// the first sent in from 1 cm away, at MuJoCo's 2 ms with the contacts inside
// the step. Before the pulse, the rounding of the placement (the last pair
// overlaps by 6.9e-18 m) pushes with 1e-17 N: the steps' inner integration
// sees depths of 1e-22 m that no position can hold, which closed at every
// step as collisions of their own (14 instead of 4, e_post -1). A contact
// whose depth the coordinates never resolve is no collision: one per pair,
// the pulse's, each with its rebound.
TEST_F(CradleTest, BallsPlacedExactlyTouchingCollideOncePerPairAtMujocosStep) {
  constexpr double r = 0.02, gap = 0.01;  // m
  std::string bodies;
  for (int i = 0; i < 5; ++i) {
    bodies += fmt::format(R"(<body name="b{0}" pos="{1} 0 1"><joint type="slide" axis="1 0 0"/>
      <geom name="b{0}" type="sphere" size="{2}" mass="0.1" group="1"/></body>)",
                          i, i == 0 ? -(2 * r + gap) : 2 * r * (i - 1), r);
  }
  const std::string xml = fmt::format(R"(<mujoco>
  <option timestep="2e-3" integrator="Euler" gravity="0 0 0"/>
  <worldbody>{}</worldbody>
  <keyframe><key qvel="1 0 0 0 0"/></keyframe>
  <custom><text name="contactlaw:chain" data="geom1=group:1 geom2=group:1 law=hertz
    stiffness=1e9"/></custom>
</mujoco>)",
                                      bodies);
  SimulationOptions options;
  options.contact_steps.substeps = kContactStepsAuto;
  Simulation& sim = MakeSimulation(xml, options);
  while (sim.time() < 0.05) sim.Step();
  std::map<int, int> per_pair;  // the tag's pairs: every two balls
  for (const Episode& c : sim.contacts().impacts()) {
    EXPECT_FALSE(c.open);
    EXPECT_TRUE(c.resolved);
    EXPECT_GT(c.separation_velocity, 0) << "pair " << c.pair;
    EXPECT_GT(c.max_depth, 1e-6) << "pair " << c.pair;  // the pulse's: 7e-5 m
    ++per_pair[c.pair];
  }
  EXPECT_EQ(per_pair.size(), 4u);  // the neighbours
  for (const auto& [pair, count] : per_pair) EXPECT_EQ(count, 1) << "pair " << pair;
}

}  // namespace
}  // namespace contactlaws
