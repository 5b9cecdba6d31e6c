// Copyright contactlaws authors.
//
// Contacts integrated inside the step (ContactStepsOptions, docs/timestep.md
// "Contact steps"): at MuJoCo's own 2 ms step under Euler, the laws keep
// their rebound, their energy and their resting depth.

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "ball_box.h"
#include "contactlaws/contactlaws.h"
#include "mujoco_test_util.h"
#include "sim/drop_reference.h"

namespace contactlaws {
namespace {

using testing::Drop;
using testing::IntegrateDrop;

// MuJoCo's default step, the one a MuJoCo user already runs at.
constexpr double kMujocoStep = 2e-3;
// The goal of issue 35: the first rebound within 0.5% of the drop's
// independent integration.
constexpr double kReboundTolerance = 5e-3;

// The default sub-steps per contact (ContactStepsOptions: 20, 80 for
// Kelvin-Voigt) are the fewest that keep the paper's ball within the auto
// timestep's default accuracy, 1e-3 of its rebound: measured 2e-4 at most
// over the five laws below, 1.1e-3 at 10 (hertz), 1.3e-3 at 8 (flores).
constexpr double kCountsRebound = 1e-3;

// The ledger's booking of the laws' dissipated power within the step (RK4's
// own quadrature of its stages' power, ContactStepper::
// dissipation_correction) against the RK4 sub-steps' own energy change:
// fourth order in the sub-step, measured 1.6e-5 of the dissipated energy
// for the bouncing ball below; the trapezoid of the sub-samples' power
// alone, second order, left 8.4e-4 of it unbooked at 20 sub-steps per
// contact.
constexpr double kLedgerTolerance = 1e-4;

SimulationOptions InnerSteps(int substeps = kContactStepsAuto) {
  SimulationOptions options;
  options.timestep = kMujocoStep;
  options.integrator = mjINT_EULER;
  options.contact_steps.substeps = substeps;
  return options;
}

class InnerContactTest : public testing::MujocoTest {};

TEST_F(InnerContactTest, ThePapersBallReboundsAsTheLawAtTwoMilliseconds) {
  const Scene scene(std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml");
  const struct {
    const char* law;
    double e;
  } cases[] = {{"flores", 0.9},
               {"hunt-crossley", 0.5},
               {"lankarani-nikravesh", 0.8},
               {"kelvin-voigt", 0.3},
               {"hertz", 1.0}};
  for (const auto& c : cases) {
    const LawId law = *ParseLawName(c.law);
    SimulationOptions options = InnerSteps();
    options.overrides.law = law;
    options.overrides.restitution = c.e;
    const Episode impact = testing::SweepFirstImpact(scene, options);
    const double reference = IntegrateDrop(Drop{}, law, c.e).restitution_post;
    EXPECT_NEAR(impact.restitution_post(), reference, kReboundTolerance * reference)
        << c.law << " e = " << c.e;
    EXPECT_NEAR(impact.restitution_post(), reference, kCountsRebound * reference)
        << c.law << " e = " << c.e;
  }
}

TEST_F(InnerContactTest, AFixedCountOfSubStepsIsTheUsers) {
  // --contact-steps 20: sub-steps of h / 20 while a point is in contact
  // (the free flight before a touch and after a separation in one), and
  // one more where a touch ends one, none divided again at a touch (a
  // touch's division read the rule's row sums, which a fixed count never
  // forms: the run crashed at the ball's first touch); 1e-4 s sub-steps
  // resolve the paper's ball within the auto rule's tolerance
  const Scene scene(std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml");
  constexpr int kSubSteps = 20;
  SimulationOptions options = InnerSteps(kSubSteps);
  options.overrides.law = *ParseLawName("flores");
  options.overrides.restitution = 0.9;
  const Episode impact = testing::SweepFirstImpact(scene, options);
  const double reference =
      IntegrateDrop(Drop{}, *options.overrides.law, 0.9).restitution_post;
  EXPECT_NEAR(impact.restitution_post(), reference, kReboundTolerance * reference);
  const std::unique_ptr<Simulation> sim = scene.Make(options);
  int most = 0;
  while (sim->time() < 1.0) {
    sim->Step();
    most = std::max(most, sim->contacts().last_substeps());
  }
  EXPECT_GT(most, 1);
  EXPECT_LE(most, kSubSteps + 1);
}

TEST_F(InnerContactTest, WithoutTheInnerStepsTheSameBallGainsEnergy) {
  // what the inner steps are for: the same 2 ms Euler step, the law at the
  // step's states, throws the ball out far faster than it came
  const Scene scene(std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml");
  SimulationOptions options = InnerSteps();
  options.contact_steps.substeps = 0;
  options.overrides.law = *ParseLawName("flores");
  options.overrides.restitution = 0.9;
  EXPECT_GT(testing::SweepFirstImpact(scene, options).restitution_post(), 2.0);
}

TEST_F(InnerContactTest, TheLedgerBooksWhatTheStepsWithContactsDissipate) {
  // over the steps whose contacts were integrated inside them, the bodies'
  // and springs' energy goes into the ledger's dissipated energy, whatever
  // Euler's free flight does in the other steps
  SimulationOptions options = InnerSteps();
  options.overrides.law = *ParseLawName("hunt-crossley");
  options.overrides.restitution = 0.5;
  Simulation& sim =
      MakeSceneSimulation("bouncing_ball.xml", options);
  auto energies = [&] {
    mj_forward(sim.model(), sim.data());
    const EnergyLedger e = sim.Energy();
    return std::pair(e.kinetic + e.potential + e.elastic, e.dissipated);
  };
  auto [mechanical, dissipated] = energies();
  double imbalance = 0;
  int inner_steps = 0;
  for (int step = 0; step < 1000; ++step) {  // 2 s: three bounces
    sim.Step();
    const auto [next_mechanical, next_dissipated] = energies();
    if (sim.contacts().last_substeps() > 0) {
      ++inner_steps;
      imbalance += (next_mechanical - mechanical) + (next_dissipated - dissipated);
    }
    mechanical = next_mechanical;
    dissipated = next_dissipated;
  }
  ASSERT_GE(sim.contacts().impacts().size(), 3u);
  ASSERT_GT(inner_steps, 0);
  EXPECT_LT(std::abs(imbalance), kLedgerTolerance * dissipated);
}

// The box stack (mjcf/box_stack.xml) at 2 ms: the top cube lands, the stack
// rocks, the middle cube lands again on the bottom one (0.224 s) while their
// face patch gains a point beside the one in contact. Its laws only take
// energy (dissipative dampers, friction), and every step with points puts all
// the bodies on the inner trajectory (Euler's own gain in free flight,
// m g^2 h^2 / 2 = 1.9e-4 J a step for a cube, included), so the mechanical
// energy rises only by the RK4 sub-steps' truncation: 4.3e-8 J at most, in
// the step that ends the top cube's landing, whose last sub-step takes the
// contact's last 1.6e-7 J of spring energy to its separation (at 50
// sub-steps per contact that step fell by 9e-8 J). The dissipated energy
// never falls (rounding: 1e-9 J leaves it six orders of room). An unbooked
// force's work shows at 1e-4 J to 1e-3 J (the patch's new point that took
// the episode of the point in contact: 1.3e-3 J).
constexpr double kStackRiseTolerance = 1e-6;  // J
constexpr double kStackFallTolerance = 1e-9;  // J

TEST_F(InnerContactTest, TheBoxStackNeitherGainsEnergyNorUnbooksWhatItDissipated) {
  Simulation& sim = MakeSceneSimulation("box_stack.xml", InnerSteps());
  double mechanical = 0, dissipated = 0, worst_rise = -1, worst_fall = -1;
  double rise_time = 0, fall_time = 0;
  for (int step = 0; step < 250; ++step) {  // 0.5 s: the landings
    sim.Step();
    ASSERT_FALSE(sim.contacts().divergence()) << "step " << step;
    mj_forward(sim.model(), sim.data());
    const EnergyLedger e = sim.Energy();
    const double next = e.kinetic + e.potential + e.elastic;
    if (step > 0 && next - mechanical > worst_rise) {
      worst_rise = next - mechanical;
      rise_time = sim.data()->time;
    }
    if (step > 0 && dissipated - e.dissipated > worst_fall) {
      worst_fall = dissipated - e.dissipated;
      fall_time = sim.data()->time;
    }
    mechanical = next;
    dissipated = e.dissipated;
  }
  EXPECT_LT(worst_rise, kStackRiseTolerance) << "at t = " << rise_time;
  EXPECT_LT(worst_fall, kStackFallTolerance) << "at t = " << fall_time;
}

TEST_F(InnerContactTest, ReadingARowLeavesTheRunsPathAlone) {
  // the stack through its landings, once with a trajectory row read after
  // every step (mj_forward, which normalizes qpos's quaternions in place)
  // and once without: the same positions, bit for bit. Reading rows used to
  // move a quaternion's last bit, which the contact steps then carried into
  // the path (a first e_post of 0.197475 with --output, 0.197473 without).
  Simulation& read = MakeSceneSimulation("box_stack.xml", InnerSteps());
  Simulation& unread = MakeSceneSimulation("box_stack.xml", InnerSteps());
  std::vector<double> row;
  for (int step = 0; step < 300; ++step) {  // 0.6 s
    read.Step();
    read.Sample(&row);
    unread.Step();
  }
  const int nq = read.model()->nq;
  const std::vector<double> a(read.data()->qpos, read.data()->qpos + nq);
  const std::vector<double> b(unread.data()->qpos, unread.data()->qpos + nq);
  EXPECT_EQ(a, b);
}

TEST_F(InnerContactTest, AResetRunsTheSamePathAgain) {
  // a cube settled on a floor (--settle: its corners' episodes open at
  // t = 0), twice for 0.2 s with Reset() between: the same positions, bit
  // for bit. The resting rule reads which points the step before found
  // calm, by their episodes; kept across the reset, the second run's first
  // step read the first run's last (its corners' episodes numbered 0-3
  // again) and rested its corners a step early
  const double depth = std::pow(9.81 / 4 / 1e7, 1 / 1.5);  // m, a quarter of the load each
  SimulationOptions settled = InnerSteps();
  settled.settle = true;
  Simulation& sim = MakeSimulation(fmt::format(R"(<mujoco>
  <option timestep="{}" integrator="Euler"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="cube" pos="0 0 {}"><freejoint/><geom name="cube" type="box" size="0.05 0.05 0.05" mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:cube" data="geom1=floor geom2=cube law=hunt-crossley
    restitution=0.5 stiffness=1e7 min_impact_velocity=0.01"/></custom>
</mujoco>)",
                                                kMujocoStep, 0.05 - depth),
                                   settled);
  std::vector<double> runs[2];
  for (auto& run : runs) {
    sim.Reset();
    for (int step = 0; step < 100; ++step) sim.Step();
    run.assign(sim.data()->qpos, sim.data()->qpos + sim.model()->nq);
  }
  EXPECT_EQ(runs[1], runs[0]);
}

// The issue's goals for a thrown die: at rest within 0.1 mm of its height,
// its mechanical energy (kinetic, potential, the laws' springs) never rising
// by more than 1e-5 J from one sample (here: step) to the next.
constexpr double kRestingHeightTolerance = 1e-4;  // m
constexpr double kEnergyRiseTolerance = 1e-5;     // J

// A frictionless cube of half size half (m) and mass (kg) dropped tilted
// from 5 cm above a floor plane, with its tag's law keys; 2 ms, Euler.
std::string DieXml(double half, double mass, const std::string& law_keys) {
  return fmt::format(R"(<mujoco>
  <option timestep="{}" integrator="Euler"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="die" pos="0 0 {}" euler="7 4 0"><freejoint/>
      <geom name="die" type="box" size="{} {} {}" mass="{}"/></body>
  </worldbody>
  <custom><text name="contactlaw:die" data="geom1=die geom2=floor {} friction=none"/></custom>
</mujoco>)",
                     kMujocoStep, half + 0.05, half, half, half, mass, law_keys);
}

TEST_F(InnerContactTest, DiceComeToRestOnTheirFourCornersWithoutGainingEnergy) {
  const struct {
    double half, mass;
    const char* keys;
  } dice[] = {
      {0.01, 0.008, "law=lankarani-nikravesh restitution=0.6 stiffness=2e8"},
      {0.025, 0.1, "law=kelvin-voigt restitution=0.3 linear_stiffness=1e5"},
      {0.05, 1.0, "law=hunt-crossley restitution=0.5 stiffness=1e7 min_impact_velocity=0.01"},
  };
  for (const auto& die : dice) {
    SCOPED_TRACE(die.keys);
    Simulation& sim = MakeSimulation(DieXml(die.half, die.mass, die.keys), InnerSteps());
    EXPECT_LT(testing::WorstMechanicalRise(sim, 1500), kEnergyRiseTolerance);  // 3 s
    // at rest flat: each corner carries a quarter of the weight
    const LawParams& law = sim.contact_model().pairs()[0].params;
    const double depth = RestingDepth(law, die.mass * 9.81 / 4);
    const int body = mj_name2id(sim.model(), mjOBJ_BODY, "die");
    EXPECT_NEAR(sim.data()->xpos[3 * body + 2], die.half - depth, kRestingHeightTolerance);
    EXPECT_LT(std::abs(sim.data()->qvel[2]), 1e-3);
  }
}


// Pairs that close their gap within one step: MuJoCo's broadphase proposes
// only the pairs near now, so the contacts integrated inside the step find
// the pairs within reach of it themselves (StepPairs). Two free balls of the
// 64-ball box (r = 5 cm, 0.125 kg, its ball-ball law) head on in zero
// gravity, 3 mm apart, closing at speed (m/s): the gap closes within the
// first 2 ms step. The untagged floor far below puts the scene under
// MuJoCo's broadphase (a scene with only tagged pairs is its own).
std::string HeadOnXml(double speed) {
  return fmt::format(R"(<mujoco>
  <option timestep="{}" integrator="Euler" gravity="0 0 0"/>
  <worldbody>
    <geom name="floor" type="plane" pos="0 0 -1" size="5 5 0.1"/>
    <body name="a" pos="-0.0515 0 0"><freejoint/>
      <geom name="a" type="sphere" size="0.05" mass="0.125"/></body>
    <body name="b" pos="0.0515 0 0"><freejoint/>
      <geom name="b" type="sphere" size="0.05" mass="0.125"/></body>
  </worldbody>
  <keyframe><key qvel="{} 0 0 0 0 0 0 0 0 0 0 0"/></keyframe>
  <custom><text name="contactlaw:balls" data="geom1=a geom2=b law=hunt-crossley
    restitution=0.8 stiffness=3.5e7 exponent=1.5 friction=none"/></custom>
</mujoco>)",
                     kMujocoStep, speed);
}

// The first episode of sim, advanced at its fixed step or at the auto
// timestep of accuracy (the fine reference).
Episode FirstEpisode(Simulation& sim, std::optional<double> accuracy = std::nullopt) {
  AdvanceOptions advance;
  advance.duration = 0.1;
  advance.until_first_episode = true;
  if (accuracy) advance.auto_timestep = AutoTimestepOptions{*accuracy};
  const AdvanceResult result = Advance(&sim, advance, nullptr);
  EXPECT_EQ(result.status, AdvanceResult::Status::kComplete);
  const std::vector<Episode>& impacts = sim.contacts().impacts();
  if (impacts.empty() || impacts.front().open) {
    ADD_FAILURE() << "no closed first episode";
    return Episode{};
  }
  return impacts.front();
}

// The fine run's accuracy, as the command line's `--timestep auto --accuracy
// 1e-6`: its rebound is the reference, 1e-6 of it.
constexpr double kFineAccuracy = 1e-6;

TEST_F(InnerContactTest, APendulumStrikingABallOnTheFloorSendsItAsTheFineRun) {
  // a 1 kg bob on a hinge swings down onto a 0.2 kg ball on the floor,
  // above its centre: it presses the ball 2.8 mm into the floor, and at the
  // peak of that squeeze both contacts' rates and net forces are near zero
  // at once. Rested there (the rule reads each point alone), the squeeze was
  // held linear over the step while it released: the ball ended 0.164 m
  // out against the fine run's 0.217 m, and the ledger's total rose by
  // 0.9 J. A point now rests only after a calm step. Frictionless; 2 ms,
  // Euler, 0.5 s; within kStrikeTolerance of `--timestep 2e-5` without
  // contact steps (0.2172 m; measured 0.2124 m)
  constexpr double kStrikeTolerance = 0.05;  // relative: the frozen configuration over the strike
  constexpr double kFineDistance = 0.2172;   // m
  Simulation& sim = MakeSimulation(R"(<mujoco>
  <option timestep="2e-3" integrator="Euler"/>
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <body name="arm" pos="0 0 0.5">
      <joint name="hinge" type="hinge" axis="0 1 0"/>
      <geom name="rod" type="capsule" fromto="0 0 0 0 0 -0.4" size="0.01" mass="0.2"/>
      <geom name="bob" type="sphere" pos="0 0 -0.42" size="0.03" mass="1"/>
    </body>
    <body name="ball" pos="0.061 0 0.03"><freejoint/><geom name="ball" type="sphere" size="0.03" mass="0.2"/></body>
  </worldbody>
  <keyframe><key qpos="-1.2  0.061 0 0.0301 1 0 0 0"/></keyframe>
  <custom>
    <text name="contactlaw:bob-ball" data="geom1=bob geom2=ball law=hunt-crossley restitution=0.8 stiffness=1e8"/>
    <text name="contactlaw:floor-ball" data="geom1=floor geom2=ball law=hunt-crossley restitution=0.5 stiffness=1e7"/>
  </custom>
</mujoco>)",
                                   InnerSteps());
  while (sim.time() < 0.5) {
    sim.Step();
    ASSERT_FALSE(sim.contacts().divergence()) << "t = " << sim.time();
  }
  EXPECT_NEAR(sim.data()->qpos[1], kFineDistance, kStrikeTolerance * kFineDistance);
}

TEST_F(InnerContactTest, BallsThatCloseTheirGapWithinOneStepReboundAsTheFineRun) {
  // head on, the normal stays the centres' line: the frozen configuration is
  // exact, and the rebound is held to the issue's 0.5% (kReboundTolerance)
  for (const double speed : {1.5, 3.0, 6.0}) {  // gap closed in 2, 1, 0.5 ms
    SCOPED_TRACE(fmt::format("{} m/s", speed));
    SimulationOptions fine_options;
    fine_options.timestep = kMujocoStep;  // the auto timestep's flight cap
    const Episode fine = FirstEpisode(MakeSimulation(HeadOnXml(speed), fine_options),
                                      kFineAccuracy);
    Simulation& sim = MakeSimulation(HeadOnXml(speed), InnerSteps());
    const Episode inner = FirstEpisode(sim);
    ASSERT_FALSE(sim.contacts().divergence());
    EXPECT_NEAR(inner.impact_velocity, fine.impact_velocity, 1e-9 * speed);
    EXPECT_NEAR(inner.restitution_post(), fine.restitution_post(),
                kReboundTolerance * fine.restitution_post());
  }
}


// Many coupled contacts in one step: balls that slide past each other turn
// their normals within the step (v_t h / s, up to 0.2 rad at 2.6 m/s past a
// 2.5 cm ball), which the frozen configuration takes to first order only
// (J + J' t, and none beyond kFrozenTurnWarning). The rise between two
// steps is not the dice's 1e-5 J here: over 41 launches of the eight balls
// (velocities scaled by 1 +- 0.046), the worst rise of each was 6.5e-5 J at
// the median and 1.3e-3 J at most, 0.14% of their 0.90 J of launch energy
// (the same before the sub-step rule left points out of contact to their
// touch: median 6.5e-5 J, largest 9.2e-4 J). Held to 3e-3 of it, over
// five launches.
constexpr double kCoupledRiseShare = 3e-3;

TEST_F(InnerContactTest, EightBallsLaunchedInABoxNeitherDivergeNorGainEnergy) {
  // the 64-ball box's scene with 8 balls: 4 mm gaps, each closing within a
  // step or two at up to 2.6 m/s, 68 pairs (MuJoCo's broadphase); 0.5 s
  const std::string xml = bench::BallBoxXml(8);
  double launch = 0, worst = 0;
  for (const double scale : {0.98, 0.99, 1.0, 1.01, 1.02}) {
    Simulation& sim = MakeSimulation(xml, InnerSteps());
    for (int k = 0; k < sim.model()->nv; ++k) sim.data()->qvel[k] *= scale;
    mj_forward(sim.model(), sim.data());
    launch = std::max(launch, sim.Energy().kinetic);
    worst = std::max(worst, testing::WorstMechanicalRise(sim, 250));
    EXPECT_GT(sim.contacts().impacts().size(), 20u) << "velocities scaled by " << scale;
  }
  EXPECT_LT(worst, kCoupledRiseShare * launch) << "launch energy " << launch << " J";
}

// The frozen configuration's measure names where it first costs accuracy,
// not only its worst step: die_throw.xml's die lands spinning at 21 rad/s,
// 0.042 rad a 2 ms step, beyond kFrozenTurnWarning from its first impact.
TEST_F(InnerContactTest, TheFirstTurnBeyondTheFrozenLimitIsTheDiesFirstImpact) {
  Simulation& sim = MakeSceneSimulation("die_throw.xml", InnerSteps());
  while (sim.time() < 0.5) sim.Step();
  ASSERT_FALSE(sim.contacts().impacts().empty());
  const double first = sim.contacts().contact_steps_first_far_turn_time();
  ASSERT_GE(first, 0) << "no step turned beyond the limit";
  EXPECT_GT(sim.contacts().contact_steps_worst_turn(), kFrozenTurnWarning);
  EXPECT_LE(first, sim.contacts().contact_steps_worst_turn_time());
  // within the steps that reach the first impact: its points are in the
  // step's reach up to two steps before it touches (the approach's margin)
  const double touch = sim.contacts().impacts()[0].time_contact;
  constexpr double kReach = 2 * kMujocoStep;  // s
  EXPECT_NEAR(first, touch, kReach) << "first impact at " << touch;
}

}  // namespace
}  // namespace contactlaws
