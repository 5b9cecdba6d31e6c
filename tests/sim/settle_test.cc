// Copyright contactlaws authors.
//
// Settle: bodies placed touching start in the static equilibrium of their
// contacts (positions only), or are refused in one line; settled, they stay
// at rest under the auto timestep.

#include "sim/settle.h"

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "sim/spelling.h"
#include "contactlaws/auto_timestep.h"
#include "mujoco_test_util.h"
#include "sim/friction_scenes.h"

namespace contactlaws {
namespace {

constexpr double kHalf = 0.05;       // cube half size, m
constexpr double kStiffness = 1e7;   // K, N/m^1.5
constexpr double kGravity = 9.81;    // m/s^2

// Three 1 kg cubes stacked on a floor, placed exactly touching (d = 0), the
// top one given qvel_top (vx) in the keyframe; the scene's timestep and
// integrator.
std::string Stack(double vx_top, const char* option = R"(timestep="1e-4" integrator="RK4")") {
  std::string bodies, tags, qpos, qvel;
  for (int i = 0; i < 3; ++i) {
    const double z = kHalf * (2 * i + 1);
    bodies += fmt::format(R"(<body name="c{0}" pos="0 0 {1}"><freejoint/>
      <geom name="c{0}" type="box" size="{2} {2} {2}" mass="1"/></body>)",
                          i, z, kHalf);
    tags += fmt::format(R"(<text name="contactlaw:t{0}" data="geom1={1} geom2=c{0}
      law=hunt-crossley restitution=0.5 stiffness={2} min_impact_velocity=1e-2"/>)",
                        i, i == 0 ? std::string("floor") : fmt::format("c{}", i - 1), kStiffness);
    qpos += fmt::format("{}0 0 {} 1 0 0 0", i ? " " : "", z);
    qvel += fmt::format("{}{} 0 0 0 0 0", i ? " " : "", i == 2 ? vx_top : 0.0);
  }
  return fmt::format(R"(<mujoco>
  <option {}/>
  <worldbody><geom name="floor" type="plane" size="2 2 0.1"/>{}</worldbody>
  <keyframe><key qpos="{}" qvel="{}"/></keyframe>
  <custom>{}</custom>
</mujoco>)",
                     option, bodies, qpos, qvel, tags);
}

// The stack's statics: each interface carries the weight above it on four
// corners, F = k W / 4 at d = (F / K)^(2/3); the centre height of cube i.
double InterfaceDepth(int k) { return std::pow((3 - k) * kGravity / 4 / kStiffness, 2.0 / 3.0); }
double SettledHeight(int i) {
  double z = 0;
  for (int k = 0; k <= i; ++k) z += 2 * kHalf - InterfaceDepth(k);
  return z - kHalf;
}
// What the relaxation leaves of cube i's height: each cube's residual
// acceleration (kSettleResidual, 1 kg) on the interfaces below it, over
// their stiffness dF/dd = 4 x 1.5 K d^0.5 (the top cube: 1.24e-10 m).
double SettledTolerance(int i) {
  double tolerance = 0;
  for (int k = 0; k <= i; ++k) {
    tolerance += (3 - k) * kSettleResidual / (4 * 1.5 * kStiffness * std::sqrt(InterfaceDepth(k)));
  }
  return tolerance;
}

class SettleTest : public testing::MujocoTest {};

TEST_F(SettleTest, AStackStartsInItsStaticEquilibriumAndDoesNotDrop) {
  SimulationOptions options;
  options.settle = true;
  Simulation& settled = MakeSimulation(Stack(0.0), options);
  Simulation& placed = MakeSimulation(Stack(0.0));
  ASSERT_TRUE(settled.settled());
  EXPECT_EQ(settled.settled()->bodies, 3);
  std::printf("%s\n", settled.settled()->Line().c_str());
  // statics (measured: the top cube 6.5e-11 m off)
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(settled.data()->qpos[7 * i + 2], SettledHeight(i), SettledTolerance(i)) << i;
  }
  // the first 0.1 s: no drop (measured: the placed stack's top cube sinks by
  // 2.7e-4 m and rings; settled, it moves 4.5e-11 m, the relaxation's
  // residual kSettleResidual ~1e-6 g acting for 0.1 s gives < 5e-8 m)
  constexpr double kNoDrop = 1e-8;  // m
  const double z_settled = settled.data()->qpos[16];
  const double z_placed = placed.data()->qpos[16];
  double drop_settled = 0, drop_placed = 0;
  while (settled.time() < 0.1) {
    settled.Step();
    placed.Step();
    drop_settled = std::max(drop_settled, std::abs(settled.data()->qpos[16] - z_settled));
    drop_placed = std::max(drop_placed, std::abs(placed.data()->qpos[16] - z_placed));
  }
  std::printf("top cube's largest move in 0.1 s: settled %.3g m, placed %.3g m\n", drop_settled,
              drop_placed);
  EXPECT_LT(drop_settled, kNoDrop);
  EXPECT_GT(drop_placed, 1e4 * kNoDrop);
}

// A scene at MuJoCo's 2 ms (Euler), whose run takes auto steps or integrates
// its contacts inside the step: the relaxation takes the auto timestep's
// steps where 2 ms would throw the laws' explicit forces apart. It diverged
// in its first step (contact steps), or called a cube unsupported (it moved
// 2.6 cm "farther than its contacts can compress": auto).
TEST_F(SettleTest, AStackAtMujocosStepSettlesToTheSameStatics) {
  for (const bool contact_steps : {false, true}) {
    SimulationOptions options;
    options.settle = true;
    if (contact_steps) options.contact_steps.substeps = kContactStepsAuto;
    Simulation& sim = MakeSimulation(Stack(0.0, R"(timestep="2e-3" integrator="Euler")"), options);
    ASSERT_TRUE(sim.settled());
    EXPECT_EQ(sim.settled()->bodies, 3);
    // (measured: the top cube 6.3e-11 m off)
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(sim.data()->qpos[7 * i + 2], SettledHeight(i), SettledTolerance(i)) << i;
    }
    // the run keeps its own step: the relaxation's shorter ones (the auto
    // timestep's, Step(h)) left the last of them as the run's, 0.2 ms
    const double z0 = sim.data()->qpos[16];
    sim.Step();
    EXPECT_EQ(sim.time(), 2e-3) << "the run's first step";
    if (!contact_steps) continue;
    // and the run at 2 ms holds it there: measured 0 m over 0.2 s; the
    // relaxation's residual (1e-6 g) would move it < 2e-7 m in that time
    constexpr double kNoDrop = 2e-7;  // m
    double drop = std::abs(sim.data()->qpos[16] - z0);
    while (sim.time() < 0.2) {
      sim.Step();
      drop = std::max(drop, std::abs(sim.data()->qpos[16] - z0));
    }
    std::printf("top cube's largest move in 0.2 s at 2 ms with contact steps: %.3g m\n", drop);
    EXPECT_LT(drop, kNoDrop);
  }
}

// box_stack.xml at its own step (RK4, 1e-4 s): the middle cube rests 1.5 cm
// off the bottom one's centre, tilted onto its offset by its load. The
// relaxation ran under RK4, whose later stages saw the cubes slid along
// their faces within the step and friction's springs stretched by it: the
// middle cube kept turning (4 rad/s^2 at 1e-4 s, 0.4 at 1e-5 s) and was
// refused as tipping. Relaxed under Euler, it settles, and it rests until the
// top cube, dropped from 5 cm, lands at 0.1 s.
TEST_F(SettleTest, TheShippedStackSettlesAtItsOwnStepUnderRk4) {
  SimulationOptions options;
  options.settle = true;
  Simulation& sim = MakeSceneSimulation("box_stack.xml", options);
  ASSERT_TRUE(sim.settled());
  EXPECT_EQ(sim.settled()->bodies, 2);
  EXPECT_EQ(sim.contacts().options().integrator, mjINT_RK4);  // the run's own, given back
  // measured: the middle cube moves 2.4e-12 m before the top one lands; the
  // relaxation's residual (1e-6 g) would move it < 4e-8 m in 0.09 s
  constexpr double kAtRest = 4e-8;  // m
  const double x0 = sim.data()->qpos[7], z0 = sim.data()->qpos[9];
  double moved = 0;
  while (sim.time() < 0.09) {
    sim.Step();
    moved = std::max(
        {moved, std::abs(sim.data()->qpos[7] - x0), std::abs(sim.data()->qpos[9] - z0)});
  }
  std::printf("box_stack.xml settled: the middle cube moved %.3g m in 0.09 s\n", moved);
  EXPECT_LT(moved, kAtRest);
}

TEST_F(SettleTest, OnlyPositionsMoveAndResetKeepsThem) {
  SimulationOptions options;
  options.settle = true;
  Simulation& sim = MakeSimulation(Stack(0.3), options);
  EXPECT_EQ(sim.time(), 0.0);
  EXPECT_EQ(sim.data()->qvel[12], 0.3);  // the scene's velocity
  const double z = sim.data()->qpos[16];
  EXPECT_LT(z, 5 * kHalf);
  sim.Step();
  sim.Reset();
  EXPECT_EQ(sim.data()->qpos[16], z);
  EXPECT_EQ(sim.data()->qvel[12], 0.3);
  // the relaxation's memory is gone: what is left is the start's three
  // contacts, open since t = 0 and touched at no speed
  ASSERT_EQ(sim.contacts().impacts().size(), 3u);
  for (const Episode& impact : sim.contacts().impacts()) {
    EXPECT_TRUE(impact.open);
    EXPECT_EQ(impact.index, 1);
    EXPECT_EQ(impact.time_contact, 0.0);
    EXPECT_EQ(impact.impact_velocity, 0.0);
  }
}

TEST_F(SettleTest, NothingInContactMovesNothing) {
  SimulationOptions options;
  options.settle = true;
  Simulation& sim = MakeSimulation(testing::DropXml("law=hertz stiffness=1e7", 1.0), options);
  ASSERT_TRUE(sim.settled());
  EXPECT_EQ(sim.settled()->bodies, 0);
  EXPECT_EQ(sim.settled()->Line(), "settle: no body touches another at t = 0: nothing moved");
  EXPECT_EQ(sim.data()->qpos[2], 0.1001);
}

// A block on a slope steeper than its friction (tan 0.6 > mu 0.5) settles
// into its contacts' depth where the scene put it, and slides from t = 0 at
// g (sin - mu cos): its contacts start sliding, at mu F_n.
TEST_F(SettleTest, ABlockOnASlopeSteeperThanItsFrictionSettlesAndSlidesFromTheStart) {
  constexpr double kTan = 0.6, kMu = 0.5;
  SimulationOptions options;
  options.settle = true;
  Simulation& sim = MakeSimulation(testing::Incline(false, kTan, "mu=0.5"), options);
  ASSERT_TRUE(sim.settled());
  EXPECT_EQ(sim.settled()->bodies, 1);
  EXPECT_EQ(sim.data()->qpos[0], 0.0);  // along the slope: the scene's
  EXPECT_EQ(sim.data()->qpos[1], 0.0);
  const double accel = testing::kG * (kTan - kMu) / std::sqrt(1 + kTan * kTan);
  constexpr double kTime = 0.2;  // s
  testing::RunUntil(sim, kTime);
  std::printf("block on tan 0.6, mu 0.5, settled: v %.6g m/s, x %.6g m at %g s (analytic %.6g, "
              "%.6g)\n", testing::Vx(sim), testing::X(sim), kTime, accel * kTime,
              0.5 * accel * kTime * kTime);
  // measured: 5.2e-3 of the speed fast: the block tips onto its downhill
  // corners at the start (friction acts 5 cm below its centre, and the
  // normal equilibrium is taken without it), and the turn's slip at its
  // corners meets friction; started with its contacts' friction unloaded
  // (it first slips until its stick springs reach mu F_n), 2.2e-2; the
  // distance 1.0e-2 and 4.3e-2
  constexpr double kSlide = 1e-2;  // relative, the speed
  constexpr double kDistance = 2e-2;  // relative
  EXPECT_NEAR(testing::Vx(sim), accel * kTime, kSlide * accel * kTime);
  EXPECT_NEAR(testing::X(sim), 0.5 * accel * kTime * kTime,
              kDistance * 0.5 * accel * kTime * kTime);
}

// On a gentler slope (tan 0.3 < mu 0.5) the block's friction holds it: its
// contacts start with the load their stick springs carry, and it stays put.
TEST_F(SettleTest, ABlockThatItsFrictionHoldsStartsHeld) {
  SimulationOptions options;
  options.settle = true;
  Simulation& sim = MakeSimulation(testing::Incline(false, 0.3, "mu=0.5"), options);
  EXPECT_EQ(sim.settled()->bodies, 1);
  const double x = testing::X(sim);
  testing::RunUntil(sim, 0.2);
  std::printf("block on tan 0.3, mu 0.5, settled: moved %.3g m along the slope in 0.2 s\n",
              testing::X(sim) - x);
  // measured 3e-10 m; unloaded friction at the start let the block slip
  // until its springs carry m g sin, by 3.4e-5 m, and tip
  constexpr double kHeld = 1e-8;  // m
  EXPECT_LT(std::abs(testing::X(sim) - x), kHeld);
}

// A ball on a slope its friction holds (tan 0.3 < 7/2 mu) has no static
// equilibrium: it rolls, as a block on a steeper slope slides. Settled into
// its contact's depth where the scene put it, it rolls from t = 0 at 5/7 g
// sin without slipping.
TEST_F(SettleTest, ABallOnASlopeItsFrictionHoldsSettlesAndRollsFromTheStart) {
  constexpr double kTan = 0.3;
  SimulationOptions options;
  options.settle = true;
  Simulation& sim = MakeSimulation(testing::Incline(true, kTan, "mu=0.5"), options);
  ASSERT_TRUE(sim.settled());
  EXPECT_EQ(sim.settled()->bodies, 1);
  EXPECT_EQ(sim.data()->qpos[0], 0.0);  // along the slope: the scene's
  const double c = 1 / std::sqrt(1 + kTan * kTan);
  const double accel = 5.0 / 7.0 * testing::kG * kTan * c;
  constexpr double kTime = 0.3;  // s
  testing::RunUntil(sim, kTime);
  std::printf("ball on tan 0.3, mu 0.5, settled: v %.6g m/s at %g s (analytic %.6g)\n",
              testing::Vx(sim), kTime, accel * kTime);
  // the lever is R - d, not R (I/(m r^2) 0.9% larger), as FrictionTest's
  // rolling ball
  constexpr double kRolling = 1e-2;  // relative
  EXPECT_NEAR(testing::Vx(sim), accel * kTime, kRolling * accel * kTime);
  const double r = testing::Lever(testing::kG * c);
  EXPECT_NEAR(testing::Vx(sim) - sim.data()->qvel[4] * r, 0, 1e-4) << "slips";
}

// A ball touching a wall beside it: gravity is along the wall, no contact
// carries it, and it would fall. Refused in one line naming it.
TEST_F(SettleTest, ABodyNoContactCarriesIsRefusedNamingIt) {
  const std::string xml = R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody>
    <geom name="wall" type="box" size="0.1 1 1" pos="-0.1 0 1"/>
    <body name="ball" pos="0.05 0 1"><freejoint/><geom name="ball" type="sphere" size="0.05"
      mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:wall" data="geom1=ball geom2=wall law=hertz stiffness=1e7"/>
  </custom>
</mujoco>)";
  SimulationOptions options;
  options.settle = true;
  try {
    MakeSimulation(xml, options);
    ADD_FAILURE() << "settled a ball beside a wall";
  } catch (const OptionError& e) {
    // the library names the option by its key; the command line by its flag
    const std::string what = e.what();
    std::printf("%s\n", what.c_str());
    EXPECT_NE(what.find(": settle: no contact carries body 'ball'"), std::string::npos) << what;
    const std::string flagged = Spelled(e, kCommandLineSpelling);
    EXPECT_NE(flagged.find(": --settle: no contact carries body 'ball'"), std::string::npos)
        << flagged;
    EXPECT_NE(what.find("it would fall"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

// A domino stood on an edge, its lowest edge 8 um into the floor: its
// contacts carry its weight, not its turn (its centre is beside the edge),
// so no resting pose exists. Tilted 12 degrees, friction holds the edge while
// it sinks to its contacts' depth: it is settled there, named as unheld, and
// tips in the run. Tilted 45 degrees, the edge slips as it sinks, so it has
// no normal equilibrium either: refused in one line that says so, naming
// it. The same domino upright settles and stays.
TEST_F(SettleTest, ABodyThatTipsStartsAtItsDepthOrIsRefusedSayingSo) {
  constexpr double kHalfThick = 0.004, kHalfHeight = 0.04, kDeep = 8e-6;  // m
  auto domino = [&](double tilt_degrees) {
    const double tilt = tilt_degrees * M_PI / 180;
    const double z = kHalfHeight * std::cos(tilt) + kHalfThick * std::sin(tilt) - kDeep;
    return fmt::format(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="domino" pos="0 0 {}" euler="0 {} 0"><freejoint/>
      <geom name="domino" type="box" size="{} 0.012 {}" mass="0.05"/></body>
  </worldbody>
  <custom><text name="contactlaw:floor" data="geom1=floor geom2=domino law=hunt-crossley
    restitution=0.3 stiffness=1e7 friction=coulomb mu=0.5"/></custom>
</mujoco>)",
                       z, tilt_degrees, kHalfThick, kHalfHeight);
  };
  SimulationOptions options;
  options.settle = true;
  // the tilt: 2 acos(qw) of the free joint's quaternion
  auto tilt = [](const Simulation& sim) { return 2 * std::acos(std::min(1.0, sim.data()->qpos[3])); };
  Simulation& tipping = MakeSimulation(domino(12), options);
  ASSERT_TRUE(tipping.settled());
  EXPECT_EQ(tipping.settled()->unheld, "domino");
  EXPECT_NE(tipping.settled()->Line().find("'domino' has no resting pose"), std::string::npos);
  const double start = tilt(tipping);
  EXPECT_NEAR(start, 12 * M_PI / 180, 1e-3);  // its turn is the scene's
  testing::RunUntil(tipping, 0.2);
  std::printf("domino at 12 degrees, settled: tilt %.4g rad at 0, %.4g rad at 0.2 s\n", start,
              tilt(tipping));
  // it tips over its edge (measured: 0.70 rad in 0.2 s); held at rest, it
  // would turn by less than a micro-radian
  constexpr double kTipped = 0.1;  // rad
  EXPECT_GT(tilt(tipping) - start, kTipped);
  try {
    MakeSimulation(domino(45), options);
    ADD_FAILURE() << "settled a domino at 45 degrees on its edge";
  } catch (const OptionError& e) {
    const std::string what = e.what();
    std::printf("%s\n", what.c_str());
    EXPECT_NE(what.find(": settle: body 'domino' tips"), std::string::npos) << what;
    // both mentions spelled: Python's "start it without settle=True"
    const std::string spoken = Spelled(e, kKeywordSpelling);
    EXPECT_NE(spoken.find(": settle=True: body 'domino' tips"), std::string::npos) << spoken;
    EXPECT_NE(spoken.find("start it without settle=True,"), std::string::npos) << spoken;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  Simulation& upright = MakeSimulation(domino(0), options);
  EXPECT_EQ(upright.settled()->bodies, 1);
  EXPECT_EQ(upright.settled()->unheld, "");
}

// A 10 kg plate (1 x 1 x 0.1 m) on a floor with 25 balls (0.5 kg, r 5 cm)
// resting on it, all placed touching, frictionless so that only the laws'
// dampers act. Settled, every contact starts at the law's floor of v0
// (1e-3 m/s): the plate's corners are stiff dampers (Hunt-Crossley's 3 (1 - e)
// / (2 v0) F, ~4e4 N s/m each under the balls' load), and the plate rocks
// against them at 1.2 c / (0.84 kg m^2 / 0.25 m^2), 3x the rate c / m of its
// mass that rule 5 took alone.
std::string PlateWithBalls() {
  std::string balls;
  for (int i = 0; i < 25; ++i) {
    balls += fmt::format(R"(<body name="b{0}" pos="{1} {2} 0.15"><freejoint/>
      <geom name="b{0}" type="sphere" size="0.05" mass="0.5" group="3"/></body>)",
                         i, -0.4 + 0.2 * (i / 5), -0.4 + 0.2 * (i % 5));
  }
  return fmt::format(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody><geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="plate" pos="0 0 0.05"><freejoint/>
      <geom name="plate" type="box" size="0.5 0.5 0.05" mass="10"/></body>{}
  </worldbody>
  <custom>
    <text name="contactlaw:plate-floor" data="geom1=plate geom2=floor law=hunt-crossley
      restitution=0.5 stiffness=1e8"/>
    <text name="contactlaw:balls-plate" data="geom1=group:3 geom2=plate law=hunt-crossley
      restitution=0.5 stiffness=1e7"/>
  </custom>
</mujoco>)",
                     balls);
}

TEST_F(SettleTest, ASettledPlateWithBallsStaysAtRestUnderAuto) {
  SimulationOptions options;
  options.settle = true;
  Simulation& sim = MakeSimulation(PlateWithBalls(), options);
  AutoTimestep stepper(sim.contacts());
  mj_forward(sim.model(), sim.data());
  const double start = sim.Energy().total();
  while (sim.time() < 0.2) sim.Step(stepper.Next(sim.data(), 0.2 - sim.time()));
  mj_forward(sim.model(), sim.data());
  const double gain = sim.Energy().total() - start;
  std::printf("settled plate with 25 balls under auto: the ledger's total %.3g J in 0.2 s of "
              "%.4g J, %ld steps\n", gain, start, stepper.steps());
  // at rest nothing acts: measured 3e-15 J in 0.5 s at a fixed 1e-5 s; the
  // ledger fed by the rocking beyond RK4's 2.785 lags, with m / c alone:
  // +0.046 J in 0.2 s (+0.11 J in 0.5 s). 1e-9 of the total.
  const double kLedgerCreep = 1e-9 * start;  // J in 0.2 s
  EXPECT_LT(std::abs(gain), kLedgerCreep);
}

}  // namespace
}  // namespace contactlaws
