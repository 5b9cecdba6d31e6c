// Copyright contactlaws authors.
//
// Friction integrated inside the step with the contacts
// (ContactStepsOptions, docs/timestep.md "Contact steps"): at MuJoCo's own
// 2 ms step under Euler, a box slides the closed-form distance, the ledger
// books what friction dissipates, a box below the friction angle stays
// where it is, and a die with friction comes to rest at the height of its
// load without gaining energy.

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contactlaws/contactlaws.h"
#include "mujoco_test_util.h"
#include "sim/friction_scenes.h"

namespace contactlaws {
namespace {

// MuJoCo's default step, the one a MuJoCo user already runs at.
constexpr double kMujocoStep = 2e-3;
constexpr double kGravity = 9.81;   // m/s^2
constexpr double kMu = 0.5;
constexpr double kHalf = 0.05;      // m, the box's half size
constexpr double kMass = 1.0;       // kg
constexpr double kStiffness = 1e7;  // N/m^1.5, the box's Hunt-Crossley K

// The slide's distance against v0^2 / (2 mu g): the stick spring's stretch
// when the box stops (mu m g over the four corners' k_t, about 20 um) and
// the sub-steps' error, within 0.1 mm of the 0.102 m slide (measured: 28 um
// short).
constexpr double kSlideTolerance = 1e-4;  // m
// The ledger's trapezoid over the sub-samples against the sub-steps' own
// energy change (backward Euler on the stick spring damps its vibration
// without booking it), relative to the 0.5 J friction dissipates (measured:
// 1.7e-6 J).
constexpr double kLedgerTolerance = 1e-3;
// A box held below its friction angle: after it settled onto its stick
// springs (its first 0.2 s), its centre moves along the slope by less than
// this in 2 s: a nanometre, against the springs' whole stretch under the
// load of 16 um (measured: 1e-15 m, roundoff).
constexpr double kStuckDrift = 1e-9;  // m

SimulationOptions InnerSteps() {
  SimulationOptions options;
  options.timestep = kMujocoStep;
  options.integrator = mjINT_EULER;
  options.contact_steps.substeps = kContactStepsAuto;
  return options;
}

// A 10 cm, 1 kg box on a floor plane under gravity tilted by slope (rad)
// about y (the same as a floor tilted by it), Hunt-Crossley with Coulomb
// friction mu; it starts at the depth of its load at rest, with velocity vx
// along x.
std::string BoxXml(double slope, double vx) {
  // Hertz's K d^1.5 carries a quarter of the load at each corner
  const double depth = std::pow(kMass * kGravity * std::cos(slope) / 4 / kStiffness, 2.0 / 3.0);
  return fmt::format(R"(<mujoco>
  <option timestep="{}" integrator="Euler" gravity="{} 0 {}"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="box" pos="0 0 {}"><freejoint/>
      <geom name="box" type="box" size="{} {} {}" mass="{}"/></body>
  </worldbody>
  <keyframe><key qpos="0 0 {} 1 0 0 0" qvel="{} 0 0 0 0 0"/></keyframe>
  <custom><text name="contactlaw:box" data="geom1=floor geom2=box law=hunt-crossley
    restitution=0.5 stiffness={} min_impact_velocity=0.01 friction=coulomb mu={}"/></custom>
</mujoco>)",
                     kMujocoStep, kGravity * std::sin(slope), -kGravity * std::cos(slope),
                     kHalf - depth, kHalf, kHalf, kHalf, kMass, kHalf - depth, vx, kStiffness,
                     kMu);
}

class InnerFrictionTest : public testing::MujocoTest {};

TEST_F(InnerFrictionTest, ABoxSlidesTheClosedFormDistanceAtTwoMilliseconds) {
  constexpr double kV0 = 1.0;  // m/s
  Simulation& sim = MakeSimulation(BoxXml(0, kV0), InnerSteps());
  mj_forward(sim.model(), sim.data());
  const EnergyLedger start = sim.Energy();
  int inner_steps = 0;
  for (int step = 0; step < 250; ++step) {  // 0.5 s: it stops at 0.2 s
    sim.Step();
    ASSERT_FALSE(sim.contacts().divergence()) << "step " << step;
    inner_steps += sim.contacts().last_substeps() > 1;
  }
  ASSERT_GT(inner_steps, 0);
  EXPECT_NEAR(sim.data()->qpos[0], kV0 * kV0 / (2 * kMu * kGravity), kSlideTolerance);
  EXPECT_LT(std::abs(sim.data()->qvel[0]), 1e-6);
  // what the box had is in the ledger: mostly friction's
  mj_forward(sim.model(), sim.data());
  const EnergyLedger end = sim.Energy();
  const double total_start = start.kinetic + start.potential + start.elastic + start.dissipated;
  const double total_end = end.kinetic + end.potential + end.elastic + end.dissipated;
  EXPECT_NEAR(total_end, total_start, kLedgerTolerance * 0.5 * kMass * kV0 * kV0);
}

TEST_F(InnerFrictionTest, ABoxBelowTheFrictionAngleStaysWhereItIs) {
  // 15 degrees (tan 0.27 < mu 0.5) holds; 35 degrees (tan 0.70) slides, so
  // that the bound tells the two apart
  const double held = 15 * M_PI / 180;
  const double slides = 35 * M_PI / 180;
  for (const double slope : {held, slides}) {
    SCOPED_TRACE(fmt::format("slope {:.0f} degrees", slope * 180 / M_PI));
    Simulation& sim = MakeSimulation(BoxXml(slope, 0), InnerSteps());
    double settled = 0;
    for (int step = 0; step < 1100; ++step) {  // 2.2 s
      sim.Step();
      ASSERT_FALSE(sim.contacts().divergence()) << "step " << step;
      if (step == 99) settled = sim.data()->qpos[0];
    }
    const double drift = std::abs(sim.data()->qpos[0] - settled);
    if (slope == held) {
      EXPECT_LT(drift, kStuckDrift);
    } else {
      // the kinetic slide: (sin - mu cos) g t^2 / 2 from rest, between 0.2
      // and 2.2 s: 3.871 m, within the 1 cm its start on the springs can
      // move it (measured: 3.866 m)
      const double a = (std::sin(slope) - kMu * std::cos(slope)) * kGravity;
      EXPECT_NEAR(drift, 0.5 * a * (2.2 * 2.2 - 0.2 * 0.2), 0.01);
    }
  }
}

// A tipping die's tilt against the fine run's, degrees: twice what Euler's
// first-order error at 2 ms moved it by in
// ADieTippingOverAnEdgeKeepsItOnTheTableAsTheFineRun (0.76).
constexpr double kTipTolerance = 1.5;

// The issue's goals for a thrown die: at rest within 0.1 mm of its height,
// its mechanical energy (kinetic, potential, the laws' springs) never rising
// by more than 1e-5 J from one sample (here: step) to the next.
constexpr double kRestingHeightTolerance = 1e-4;  // m
constexpr double kEnergyRiseTolerance = 1e-5;     // J

TEST_F(InnerFrictionTest, ADieWithFrictionComesToRestWithoutGainingEnergy) {
  // a 2 cm, 8 g die of die_throw.xml's law and friction, thrown spinning
  // onto a floor plane from 5 cm
  const std::string xml = fmt::format(R"(<mujoco>
  <option timestep="{}" integrator="Euler"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="die" pos="0 0 0.06" euler="7 4 0"><freejoint/>
      <geom name="die" type="box" size="0.01 0.01 0.01" mass="0.008"/></body>
  </worldbody>
  <keyframe><key qpos="0 0 0.06 0.9509 0.1892 0.2303 0.0838" qvel="0.8 0 0 3 20 5"/></keyframe>
  <custom><text name="contactlaw:die" data="geom1=die geom2=floor law=lankarani-nikravesh
    restitution=0.6 stiffness=2e8 friction=coulomb mu=0.4"/></custom>
</mujoco>)",
                                      kMujocoStep);
  Simulation& sim = MakeSimulation(xml, InnerSteps());
  EXPECT_LT(testing::WorstMechanicalRise(sim, 1500), kEnergyRiseTolerance);  // 3 s
  // at rest flat: each corner carries a quarter of the weight
  const LawParams& law = sim.contact_model().pairs()[0].params;
  const double depth = RestingDepth(law, 0.008 * kGravity / 4);
  const int body = mj_name2id(sim.model(), mjOBJ_BODY, "die");
  EXPECT_NEAR(sim.data()->xpos[3 * body + 2], 0.01 - depth, kRestingHeightTolerance);
  EXPECT_LT(mju_norm(sim.data()->qvel, 6), 1e-3);
  // at rest its corners' forces are implicit: one sub-step a step, where
  // its 0.2 ms contact would take 470 explicit ones
  EXPECT_EQ(sim.contacts().last_substeps(), 1);
}

// A die let go just above the depth its four corners carry it at: it comes
// to rest there, and then each step is one backward-Euler sub-step
// (docs/timestep.md, "Contacts at rest"). Its corners' vibration (omega h =
// 17) is not resolved by one sub-step: a resting step that took the start's
// unbalanced force over the step exactly (h^2 / 2) and only its change by
// backward Euler (h^2) left the corners a rate of h a / 2 (a: that
// imbalance), whose carry over the next step, h^2 a / 2, was above the
// resting rule's 10% of the depth for any imbalance above 0.1% of g: the
// steps then went 470 sub-steps and 1 in turn to the end (600,000 in 5 s).
TEST_F(InnerFrictionTest, ADieLetGoAboveItsRestingDepthSettlesIntoOneSubStepAStep) {
  constexpr double kLoad = 0.008 * kGravity / 4;  // N, per corner
  constexpr double kAbove = 5e-7;                 // m, above the surface at rest
  constexpr double kStiffness = 2e8;             // N/m^1.5
  constexpr double kSettledHeight = 1e-12;        // m
  constexpr double kSettledSpeed = 1e-9;          // m/s
  // K d^1.5 carries the load at rest
  const double depth = std::pow(kLoad / kStiffness, 2.0 / 3.0);
  const std::string xml = fmt::format(R"(<mujoco>
  <option timestep="{}" integrator="Euler"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="die" pos="0 0 {}"><freejoint/>
      <geom name="die" type="box" size="0.01 0.01 0.01" mass="0.008"/></body>
  </worldbody>
  <custom><text name="contactlaw:die" data="geom1=die geom2=floor law=lankarani-nikravesh
    restitution=0.6 stiffness={} friction=coulomb mu=0.4"/></custom>
</mujoco>)",
                                      kMujocoStep, 0.01 - depth + kAbove, kStiffness);
  Simulation& sim = MakeSimulation(xml, InnerSteps());
  // its first bounces (0.5 s), then 2 s at rest
  EXPECT_LT(testing::WorstMechanicalRise(sim, 250), kEnergyRiseTolerance);
  int substeps = 0;
  constexpr int kSteps = 1000;
  for (int step = 0; step < kSteps; ++step) {
    sim.Step();
    substeps += sim.contacts().last_substeps();
  }
  EXPECT_EQ(substeps, kSteps);
  // at the law's own depth under its load: backward Euler's equilibrium is
  // the law's, to roundoff (measured: 0 m off, 2e-16 m/s): 1e-12 m is 5e-6
  // of the 0.21 um depth, 1e-9 m/s a nanometre a second
  const int body = mj_name2id(sim.model(), mjOBJ_BODY, "die");
  EXPECT_NEAR(sim.data()->xpos[3 * body + 2], 0.01 - depth, kSettledHeight);
  EXPECT_LT(mju_norm(sim.data()->qvel, 6), kSettledSpeed);
}

// A die stood on an edge 5 degrees past balance tips over it onto a face.
// Beyond 0.01 rad a step (5 rad/s) its edge's rows keep the frozen J, and
// without J' v0 (the edge's acceleration relative to the die's centre, r
// w^2) the edge lifted by r w^2 h^2 / 2 a step against the inner
// trajectory: it left the table at 5.7 rad/s and bounced on it at every
// step, where the fine run keeps it in contact until the face lands
// (docs/timestep.md, "Carried or struck").
TEST_F(InnerFrictionTest, ADieTippingOverAnEdgeKeepsItOnTheTableAsTheFineRun) {
  constexpr double kTilt = 40;  // degrees from flat on its face
  constexpr double kHalf = 0.01;
  // the edge at about its depth under the die's weight
  const double z = kHalf * (std::cos(kTilt * M_PI / 180) + std::sin(kTilt * M_PI / 180)) - 2.5e-7;
  const std::string xml = fmt::format(R"(<mujoco>
  <option timestep="{}" integrator="Euler"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="die" pos="0 0 {}" euler="0 {} 0"><freejoint/>
      <geom name="die" type="box" size="{} {} {}" mass="0.008"/></body>
  </worldbody>
  <custom><text name="contactlaw:die" data="geom1=die geom2=floor law=lankarani-nikravesh
    restitution=0.6 stiffness=2e8 friction=coulomb mu=0.4"/></custom>
</mujoco>)",
                                      kMujocoStep, z, kTilt, kHalf, kHalf, kHalf);
  // up to 7 rad/s (0.014 rad a step): the edge in contact at every step
  constexpr double kSpin = 7;  // rad/s
  Simulation& sim = MakeSimulation(xml, InnerSteps());
  const auto spin = [](const Simulation& s) { return mju_norm3(s.data()->qvel + 3); };
  const auto tilt = [](const Simulation& s) {
    return std::acos(std::min(1.0, std::abs(s.data()->xmat[9 + 8]))) * 180 / M_PI;
  };
  int lifted = 0;
  while (spin(sim) < kSpin && sim.time() < 0.5) {
    sim.Step();
    lifted += sim.contacts().latest().empty();
  }
  EXPECT_EQ(lifted, 0) << "the edge left the table before " << sim.time() << " s";
  EXPECT_GE(spin(sim), kSpin);
  // the tilt then against the fine run's (RK4 at 1e-5 s, without contact
  // steps) at the same time (0.088 s): the outer step is Euler's, whose
  // first-order error lags the tip (measured: 0.76 degrees behind the 13.9
  // the fine run turned by then)
  SimulationOptions fine;
  fine.timestep = 1e-5;
  fine.integrator = mjINT_RK4;
  Simulation& reference = MakeSimulation(xml, fine);
  while (reference.time() < sim.time() - 0.5e-5) reference.Step();
  EXPECT_NEAR(tilt(sim), tilt(reference), kTipTolerance);
}

// The closed forms of friction_test.cc's soft scenes (K = 1e6), there at
// 1e-4 s and RK4, here at 2 ms and Euler with contact steps, with their
// tolerances (friction_scenes.h).
TEST_F(InnerFrictionTest, TheFrictionScenesKeepTheirClosedFormsAtTwoMilliseconds) {
  for (const char* model : {"coulomb", "lugre"}) {
    SCOPED_TRACE(model);
    Simulation& sim = MakeSimulation(
        testing::FrictionScene(false, 0, kGravity, "1 0 0 0 0 0",
                               fmt::format("friction={} mu=0.4", model)),
        InnerSteps());
    mj_forward(sim.model(), sim.data());
    const double start = sim.Energy().total();
    testing::RunUntil(sim, 0.5);
    testing::ExpectKineticStop(sim, 0.4, 1.0, start, model);
  }
  // gross sliding in an oblique impact: the impulse law
  constexpr double kObliqueMu = 0.2;
  Simulation& sim = MakeSimulation(testing::ObliqueImpact(2, kObliqueMu), InnerSteps());
  while (sim.contacts().impacts().empty() || sim.contacts().impacts()[0].open) sim.Step();
  testing::ExpectImpulseLaw(sim, sim.contacts().impacts()[0], kObliqueMu, 2, "oblique");
}

TEST_F(InnerFrictionTest, ASeparationAtAStepsStartIsReadAtTheSpeedTheBallLeavesWith) {
  // the oblique impact's ball leaves spinning (w R = 0.82 m/s) and sliding
  // (1.67 m/s), no gravity: its normal speed after the impact is the
  // rebound's. At some counts of sub-steps per contact its last sub-step in
  // contact ends a step, and the separation was read at the next step's
  // start from the bodies' velocity at the point last in contact, a
  // material point the spin had carried v_t h past the contact: w v_t h =
  // 0.027 m/s too fast (e_post 0.6903 against 0.6630 at 20 and 30 sub-steps
  // per contact). The rows' rate at the step's end against the bodies' is
  // the frozen configuration's (measured 8e-6 of it).
  constexpr double kSeparationTolerance = 1e-4;  // relative
  for (const double per_contact : {20.0, 25.0, 30.0, 40.0, 50.0}) {
    SimulationOptions options = InnerSteps();
    options.contact_steps.per_contact_hertz = per_contact;
    Simulation& sim = MakeSimulation(testing::ObliqueImpact(2, 0.2), options);
    while (sim.contacts().impacts().empty() || sim.contacts().impacts()[0].open) sim.Step();
    const double leaves = sim.data()->qvel[2];
    EXPECT_NEAR(sim.contacts().impacts()[0].separation_velocity, leaves,
                kSeparationTolerance * leaves)
        << per_contact << " sub-steps per contact";
  }
}

TEST_F(InnerFrictionTest, ABallSlidesThenRollsAtFiveSeventhsAtTwoMilliseconds) {
  // the tangential rows turn the ball: its slip closes at mu g (1 + m r^2 /
  // I) and it rolls on at 5/7 v0, the lever r = R less half the depth
  constexpr double kBallMu = 0.3;
  constexpr double kV0 = 2.0;
  Simulation& sim = MakeSimulation(
      testing::FrictionScene(true, 0, kGravity, fmt::format("{} 0 0 0 0 0", kV0),
                             fmt::format("mu={}", kBallMu)),
      InnerSteps());
  const double r = testing::Lever(kGravity);
  const double inertia = 0.4 * testing::kRadius * testing::kRadius;
  const double t_roll = kV0 / (kBallMu * kGravity * (1 + r * r / inertia));
  testing::RunUntil(sim, 0.95 * t_roll);
  EXPECT_GT(testing::Vx(sim) - testing::Wy(sim) * r, 0.01) << "still sliding before t_roll";
  testing::RunUntil(sim, 1.05 * t_roll + 0.05);
  // friction_test's tolerance (the stick spring's stretch when it
  // catches), and the step's own error: the stick anchors are the material
  // points of a step's start, and the ball's one rises off the floor as it
  // rolls by theta = w h, falling behind the contact by r theta^3 / 6 a
  // step, which the spring takes as a slip of v^3 h^2 / (6 r^2): 1.9e-4 m/s
  // at 1.43 m/s and 2 ms (measured: v and w r 8.2e-5 below and 2.0e-4
  // above 5/7 v0, steady; the ball rests on its contact, whose one
  // backward-Euler sub-step a step adds to the anchors' slip)
  constexpr double kRollingTolerance = 1e-4;  // m/s
  const double rolling = kV0 * r / (r + inertia / r);
  const double anchor_slip = std::pow(rolling, 3) * kMujocoStep * kMujocoStep / (6 * r * r);
  EXPECT_NEAR(testing::Vx(sim), rolling, kRollingTolerance);
  EXPECT_NEAR(testing::Wy(sim) * r, rolling, kRollingTolerance + anchor_slip);
}

// A body of radius kRollRadius on its side on the floor, 10 um deep, moving
// at vx along x and turning at wy about y (geom: the shape's keys; its axis
// along y), Hunt-Crossley with Coulomb friction mu; 2 ms, Euler.
constexpr double kRollRadius = 0.03;  // m
std::string SideXml(const std::string& geom, double z, double vx, double wy) {
  return fmt::format(R"(<mujoco>
  <option timestep="{}" integrator="Euler"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="body" pos="0 0 {}"><freejoint/><geom name="body" {} mass="0.5"/></body>
  </worldbody>
  <keyframe><key qpos="0 0 {} 1 0 0 0" qvel="{} 0 0 0 {} 0"/></keyframe>
  <custom><text name="contactlaw:body" data="geom1=floor geom2=body law=hunt-crossley
    restitution=0.5 stiffness={} friction=coulomb mu={}"/></custom>
</mujoco>)",
                     kMujocoStep, z, geom, z, vx, wy, kStiffness, kMu);
}

// The ledger's total (kinetic, potential, elastic, dissipated) at the end of
// sim run for seconds, less the one at its start.
double LedgerDrift(Simulation& sim, double seconds) {
  mj_forward(sim.model(), sim.data());
  const EnergyLedger start = sim.Energy();
  while (sim.time() < seconds) {
    sim.Step();
    if (sim.contacts().divergence()) return std::numeric_limits<double>::infinity();
  }
  mj_forward(sim.model(), sim.data());
  const EnergyLedger end = sim.Energy();
  return (end.kinetic + end.potential + end.elastic + end.dissipated) -
         (start.kinetic + start.potential + start.elastic + start.dissipated);
}

TEST_F(InnerFrictionTest, ACapsuleOrACylinderRollingOnItsSideBooksNoDissipation) {
  // rolling at 1.5 m/s (w r = v): nothing slides and nothing dissipates.
  // Their contact points roll over the surface: the depth is carried by the
  // axis (RollingCentre), not by the material point at the contact, whose
  // centripetal r w^2 = 75 m/s^2 the rows took as a lift of the contact
  // every step (the ledger booked 0.48 J of damping in 0.3 s). So does a
  // spheroid rolling on its round section: its support point rolls over
  // its surface (AddDepthJacobianRate); at the material point the ledger's
  // total rose 0.42 J in 0.3 s (5.6 J in 2 s). Held to
  // kRollingLedger of the kinetic energy: the rolling stick springs'
  // anchors rise off the floor with the material point (the ball's above)
  // and book a little (measured -2.7e-5, -2.2e-5 and -6.9e-5 J, against
  // 0.56 J of translation).
  constexpr double kRollingLedger = 2e-3;
  constexpr double kV = 1.5;
  const double kinetic = 0.5 * 0.5 * kV * kV;  // J, the translation's alone
  for (const std::string& geom : {fmt::format(R"(type="capsule" size="{} 0.08" euler="90 0 0")",
                                              kRollRadius),
                                  fmt::format(R"(type="cylinder" size="{} 0.08" euler="90 0 0")",
                                              kRollRadius),
                                  fmt::format(R"(type="ellipsoid" size="{0} {0} 0.05" euler="90 0 0")",
                                              kRollRadius)}) {
    Simulation& sim =
        MakeSimulation(SideXml(geom, kRollRadius - 1e-5, kV, kV / kRollRadius), InnerSteps());
    EXPECT_LT(std::abs(LedgerDrift(sim, 0.3)), kRollingLedger * kinetic) << geom;
    // it rolls on, as the ball above: within the anchors' slip v^3 h^2 /
    // (6 r^2), 2.5e-3 m/s here (measured 1.1e-3 m/s below 1.5 m/s)
    const double anchor_slip = std::pow(kV, 3) * kMujocoStep * kMujocoStep /
                               (6 * kRollRadius * kRollRadius);
    EXPECT_NEAR(sim.data()->qvel[0], kV, anchor_slip) << geom;
  }
}

TEST_F(InnerFrictionTest, ABallOnASlopeRunsItsClosedFormPathAndKeepsItsEnergy) {
  // a ball settled on a 10-degree slope (gravity tilted), its contact at
  // rest along the normal: frictionless it slides at g sin, x = g sin t^2 /
  // 2 exactly (RK4's free flight); with coulomb it rolls. The resting rule's
  // backward Euler in position was added to every dof of the ball, so that
  // it ran h a t / 2 ahead along the slope (1.4 mm at 1 s) and the ledger's
  // total fell 2.9e-3 J (frictionless) and 2.1e-3 J (rolling) in 1 s; now
  // only along its resting rows. Measured: x exact to 1e-12 m, the totals
  // 9e-15 J and -8.2e-6 J (the rolling stick springs' anchors, as above).
  constexpr double kSlope = 10 * M_PI / 180;
  constexpr double kPathTolerance = 1e-9;     // m, against 1.4e-3 m
  constexpr double kSlidingLedger = 1e-9;     // J, against 2.9e-3 J
  constexpr double kRollingLedger = 1e-4;     // J, against 2.1e-3 J
  for (const char* friction : {"none", "coulomb"}) {
    SCOPED_TRACE(friction);
    SimulationOptions options = InnerSteps();
    options.settle = true;
    Simulation& sim = MakeSimulation(fmt::format(R"(<mujoco>
  <option gravity="{} 0 {}"/>
  <worldbody>
    <geom name="floor" type="plane" size="50 50 0.1"/>
    <body name="ball" pos="0 0 0.05"><freejoint/><geom name="ball" type="sphere" size="0.05" mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:c" data="geom1=floor geom2=ball law=hunt-crossley restitution=0.5
    stiffness=1e7 friction={} mu=0.3"/></custom>
</mujoco>)", 9.81 * std::sin(kSlope), -9.81 * std::cos(kSlope), friction),
                                     options);
    const double drift = LedgerDrift(sim, 1.0);
    if (std::string(friction) == "none") {
      const double t = sim.time();
      EXPECT_NEAR(sim.data()->qpos[0], 0.5 * 9.81 * std::sin(kSlope) * t * t, kPathTolerance);
      EXPECT_LT(std::abs(drift), kSlidingLedger);
    } else {
      EXPECT_LT(std::abs(drift), kRollingLedger);
    }
  }
}

TEST_F(InnerFrictionTest, ABoxPlacedTouchingSlidesAndBooksWhatFrictionDissipates) {
  // placed at d = 0 exactly and sliding: its corners enter the floor at
  // once, pushed by gravity from rest along the normal. Their touch is now,
  // not a whole sub-step later (the step's, 2 ms, which a point out of
  // contact does not shorten): taken then, 20 um deep with no force behind
  // them, the ledger rose by 0.041 J of 0.56 J.
  constexpr double kV = 1.5;
  Simulation& sim = MakeSimulation(
      SideXml(R"(type="box" size="0.03 0.08 0.03")", 0.03, kV, 0), InnerSteps());
  EXPECT_LT(std::abs(LedgerDrift(sim, 0.3)), kLedgerTolerance * 0.5 * 0.5 * kV * kV);
}

}  // namespace
}  // namespace contactlaws
