// Copyright contactlaws authors.
//
// The laws inside MuJoCo against closed forms. Gravity is off where the
// closed form neglects it; the ball starts 0.1 mm above the floor.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "contactlaws/law.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

using testing::DropXml;
using testing::FirstImpact;

class PhysicsTest : public testing::MujocoTest {};

constexpr double kStiffness = 1.4e8;  // the paper's K, N/m^1.5
constexpr double kSpeed = 4.2;        // m/s, about the paper's 0.9 m fall

std::string LawTag(LawId law, double e) {
  return fmt::format("law={} restitution={} stiffness={} exponent=1.5", LawName(law), e,
                     kStiffness);
}

// e_post of the Hertz family against the root of a (1 + e) = ln((1+a)/(1-a e)).
// Tolerance: the contact (~1.3 ms) is resolved in ~130 steps of 1e-5 s; the
// semi-implicit Euler step and reading first touch and separation at step
// granularity leave errors measured at <= 6e-5 over this grid (largest for
// e = 1, where separation happens at the fastest approach to d = 0): 2e-4
// leaves room for other compilers' rounding, and is 10x tighter than the 2e-3
// the comparison harness promises.
constexpr double kReboundTolerance = 2e-4;

TEST_F(PhysicsTest, HertzFamilyReboundMatchesClosedForm) {
  for (LawId law : {*ParseLawName("hunt-crossley"), *ParseLawName("lankarani-nikravesh"),
                      *ParseLawName("flores")}) {
    for (int tenths = 1; tenths <= 10; ++tenths) {
      const double e = tenths / 10.0;
      Simulation& sim = MakeSimulation(DropXml(LawTag(law, e), kSpeed));
      const Episode impact = FirstImpact(sim);
      const double expected = ExactRebound(HysteresisCoefficient(law, e));
      EXPECT_NEAR(impact.restitution_post(), expected, kReboundTolerance)
          << LawName(law) << " e = " << e;
      // gravity off: no force acts before the first state in contact
      EXPECT_NEAR(impact.impact_velocity, kSpeed, 1e-12);
    }
  }
}

TEST_F(PhysicsTest, HertzMaxDepthMatchesClosedForm) {
  // delta_max = (5 m v^2 / (4 K))^(2/5). Tolerance: the maximum is sampled at
  // steps of 1e-5 s where d' ~ 0, so sampling costs O((h/tau)^2); the
  // integrator's energy error near the turning point is ~1e-4 relative.
  constexpr double kDepthTolerance = 1e-3;  // relative
  for (double v : {0.5, 2.0, kSpeed}) {
    Simulation& sim = MakeSimulation(DropXml(LawTag(*ParseLawName("hertz"), 1.0), v));
    const Episode impact = FirstImpact(sim);
    const double expected = std::pow(5 * 1.0 * v * v / (4 * kStiffness), 0.4);
    EXPECT_NEAR(impact.max_depth / expected, 1.0, kDepthTolerance) << "v = " << v;
    EXPECT_NEAR(impact.restitution_post(), 1.0, kReboundTolerance);
  }
}

}  // namespace
}  // namespace contactlaws

namespace contactlaws {
namespace {

using testing::DropXml;
using testing::FirstImpact;

class LedgerTest : public testing::MujocoTest {};

TEST_F(LedgerTest, HertzConservesEnergy) {
  // The paper's ball, switched to Hertz, falls 0.9 m with gravity and
  // bounces twice in 2 s. total = kinetic + potential + elastic + dissipated
  // must stay at its start:
  // - RK4: everywhere to 1e-5 (measured 1.9e-6);
  // - semi-implicit Euler is symplectic: no drift across contacts (1e-4 out
  //   of contact, measured 2.2e-5), but inside a contact its energy
  //   oscillates by ~ h omega / 2 = 1e-5 * (pi / 1.3 ms) / 2 = 1.2% (measured
  //   1.17%): held to 2%.
  const std::string path = std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/bouncing_ball.xml";
  for (int integrator : {mjINT_RK4, mjINT_EULER}) {
    SimulationOptions options;
    options.overrides.law = *ParseLawName("hertz");
    options.integrator = integrator;
    Simulation sim(LoadModelFile(path), "bouncing_ball.xml", options);
    mj_forward(sim.model(), sim.data());
    const double start = sim.Energy().total();
    EXPECT_NEAR(start, 9.81, 1e-12) << "m g h, h = 1 m";
    double worst_in = 0, worst_out = 0;
    for (int step = 1; sim.time() < 2.0; ++step) {
      sim.Step();
      if (step % 10) continue;
      mj_forward(sim.model(), sim.data());
      const double error = std::abs(sim.Energy().total() / start - 1);
      (sim.Energy().elastic > 0 ? worst_in : worst_out) =
          std::max(error, sim.Energy().elastic > 0 ? worst_in : worst_out);
      ASSERT_EQ(sim.Energy().dissipated, 0.0);
    }
    CheckNoWarnings(sim.data());
    EXPECT_EQ(sim.contacts().impacts().size(), 2u);
    if (integrator == mjINT_RK4) {
      EXPECT_LT(std::max(worst_in, worst_out), 1e-5);
    } else {
      EXPECT_LT(worst_out, 1e-4);
      EXPECT_LT(worst_in, 2e-2);
      EXPECT_GT(worst_in, 1e-3) << "the oscillation the bound explains is there";
    }
  }
}

TEST_F(LedgerTest, DissipationMatchesTheKineticEnergyLost) {
  // Flores e = 0.5, gravity off: after the episode, dissipated = the kinetic
  // energy lost, 1/2 m v0^2 (1 - e_post^2). The ledger integrates the damping
  // power sampled once per step (trapezoid), while the step itself is
  // semi-implicit Euler: they differ by O(h / tau), measured 0.7% at
  // h = 1e-5 s for this 1.5 ms contact. Held to 1%, and to first-order
  // convergence: ten times smaller step, at least five times smaller error.
  double error[2];
  const double steps[2] = {1e-5, 1e-6};
  for (int i = 0; i < 2; ++i) {
    Simulation& sim =
        MakeSimulation(DropXml(LawTag(*ParseLawName("flores"), 0.5), 2.0, "Euler", steps[i]));
    const Episode impact = FirstImpact(sim);
    sim.Step();  // one more step: the ledger's trapezoid reaches the separation
    mj_forward(sim.model(), sim.data());
    const double lost = 0.5 * 1.0 * 4.0 * (1 - std::pow(impact.restitution_post(), 2));
    error[i] = std::abs(sim.Energy().dissipated / lost - 1);
    EXPECT_NEAR(sim.Energy().elastic, 0.0, 1e-12);
  }
  EXPECT_LT(error[0], 1e-2);
  EXPECT_LT(error[1], error[0] / 5);
}

class TwoSpheresTest : public testing::MujocoTest {
 protected:
  // Two free spheres, masses 1 and 3 kg, meeting head-on along x.
  static std::string Xml(std::string_view tag) {
    return fmt::format(R"(
<mujoco>
  <option timestep="1e-5" gravity="0 0 0"/>
  <worldbody>
    <body name="a" pos="-0.1001 0 1"><freejoint/>
      <inertial pos="0 0 0" mass="1" diaginertia="0.004 0.004 0.004"/>
      <geom name="a" type="sphere" size="0.1"/></body>
    <body name="b" pos="0.1001 0 1"><freejoint/>
      <inertial pos="0 0 0" mass="3" diaginertia="0.012 0.012 0.012"/>
      <geom name="b" type="sphere" size="0.1"/></body>
  </worldbody>
  <keyframe><key qvel="2 0 0 0 0 0  -1 0 0 0 0 0"/></keyframe>
  <custom><text name="contactlaw:a-b" data="geom1=a geom2=b {}"/></custom>
</mujoco>)",
                       tag);
  }
};

TEST_F(TwoSpheresTest, MomentumAndPaperEquations13To15) {
  constexpr double m1 = 1, m2 = 3, v1 = 2, v2 = -1;
  Simulation& sim = MakeSimulation(Xml(LawTag(*ParseLawName("flores"), 0.7)));
  const Episode impact = FirstImpact(sim);
  EXPECT_NEAR(impact.impact_velocity, v1 - v2, 1e-12);  // no force before touch
  const double* qvel = sim.data()->qvel;
  // momentum: the pair's forces are equal and opposite at one point, so it is
  // conserved to rounding
  EXPECT_NEAR(m1 * qvel[0] + m2 * qvel[6], m1 * v1 + m2 * v2, 1e-9);
  // eqs. 13-14 with c_r the measured rebound (tolerance as the rebound's,
  // times the velocities' scale 3 m/s)
  const double c = impact.restitution_post();
  EXPECT_NEAR(c, ExactRebound(HysteresisCoefficient(*ParseLawName("flores"), 0.7)), 2e-4);
  EXPECT_NEAR(qvel[0], ((m1 - c * m2) * v1 + (1 + c) * m2 * v2) / (m1 + m2), 6e-4);
  EXPECT_NEAR(qvel[6], ((m2 - c * m1) * v2 + (1 + c) * m1 * v1) / (m1 + m2), 6e-4);
  // eq. 15: energy dissipated (ledger accurate to O(h / tau), see LedgerTest)
  mj_forward(sim.model(), sim.data());
  const double dissipated = 0.5 * m1 * m2 / (m1 + m2) * 9 * (1 - c * c);
  EXPECT_NEAR(sim.Energy().dissipated / dissipated, 1.0, 1e-2);
  // no spin from a central contact
  for (int k : {3, 4, 5, 9, 10, 11}) EXPECT_NEAR(qvel[k], 0.0, 1e-9);
}

TEST_F(TwoSpheresTest, KelvinVoigtUsesTheEffectiveMass) {
  // With tension allowed, the linear oscillator of mass m_eff = m1 m2/(m1+m2)
  // = 0.75 kg rebounds with exactly e when c = 2 zeta(e) sqrt(k m_eff): a
  // wrong m_eff (1 or 3 kg) would miss by > 0.05. Tolerance: the force jumps
  // by c v0 at first touch, an O(h / tau) = 1e-5 / 1.2e-3 error on e.
  for (double e : {0.3, 0.6, 0.9}) {
    Simulation& sim = MakeSimulation(
        Xml(fmt::format("law=kelvin-voigt restitution={} linear_stiffness=5e6 "
                        "allow_tension=true",
                        e)));
    EXPECT_NEAR(FirstImpact(sim).restitution_post(), e, 1e-2) << "e = " << e;
  }
}

TEST_F(PhysicsTest, KelvinVoigtClampedReboundsAboveE) {
  // Clamped to F >= 0, Kelvin-Voigt separates before d returns to 0 and
  // keeps more energy: e_post > e (the paper's criticism of the model).
  Simulation& sim = MakeSimulation(
      DropXml("law=kelvin-voigt restitution=0.5 linear_stiffness=5e6", 2.0));
  const Episode impact = FirstImpact(sim);
  EXPECT_GT(impact.restitution_post(), 0.5 + 0.02);
  EXPECT_LT(impact.restitution_post(), 1.0);
}

TEST_F(PhysicsTest, RungeKuttaEulerAndImplicitAgree) {
  // The memory is committed once per accepted step, so RK4's four hook
  // calls give the same physics. Tolerance: each integrator's own error,
  // <= 6e-5 for Euler (above), smaller for RK4.
  for (LawId law : {*ParseLawName("hunt-crossley"), *ParseLawName("flores")}) {
    double e_post[3];
    const char* integrators[3] = {"Euler", "RK4", "implicit"};
    for (int i = 0; i < 3; ++i) {
      Simulation& sim = MakeSimulation(DropXml(LawTag(law, 0.5), kSpeed, integrators[i]));
      e_post[i] = FirstImpact(sim).restitution_post();
    }
    const double exact = ExactRebound(HysteresisCoefficient(law, 0.5));
    EXPECT_NEAR(e_post[1], exact, 2e-5) << LawName(law) << " RK4";
    EXPECT_NEAR(e_post[0], e_post[1], kReboundTolerance) << LawName(law);
    EXPECT_NEAR(e_post[2], e_post[1], kReboundTolerance) << LawName(law);
  }
}

TEST_F(PhysicsTest, MaterialStiffnessFromTheGeoms) {
  // steel ball (R = 0.1) on a steel plane: K = 4/(3 * 2s) sqrt(0.1),
  // s = (1 - 0.3^2)/2.1e11  ->  K = 4.8654e10 N/m^1.5. So stiff a contact
  // lasts ~0.2 ms: a 1e-6 s step resolves it as 1e-5 s does the paper's.
  Simulation& sim = MakeSimulation(DropXml(
      "law=flores restitution=0.8 youngs1=2.1e11 poisson1=0.3 youngs2=2.1e11 poisson2=0.3",
      1.0, "Euler", 1e-6));
  const double s = 0.91 / 2.1e11;
  const double expected = 4.0 / (3.0 * 2 * s) * std::sqrt(0.1);
  EXPECT_NEAR(sim.contact_model().pairs()[0].params.stiffness / expected, 1.0, 1e-12);
  EXPECT_NEAR(expected, 4.8654e10, 1e7);
  // and it acts: the rebound and the Hertz-family depth bound for that K
  const Episode impact = FirstImpact(sim);
  EXPECT_NEAR(impact.restitution_post(),
              ExactRebound(HysteresisCoefficient(*ParseLawName("flores"), 0.8)), kReboundTolerance);
  EXPECT_LT(impact.max_depth, std::pow(5.0 / (4 * expected), 0.4));
  EXPECT_GT(impact.max_depth, 0.5 * std::pow(5.0 / (4 * expected), 0.4));
}

TEST_F(PhysicsTest, GroupTagsCoverEveryPair) {
  // three balls in group 1, the floor in group 2, one tag for all of them
  Simulation& sim = MakeSimulation(R"(
<mujoco>
  <option timestep="1e-5" gravity="0 0 0"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1" group="2"/>
    <body pos="0 0 0.1001"><freejoint/><geom type="sphere" size="0.1" mass="1" group="1"/></body>
    <body pos="1 0 0.1001"><freejoint/><geom type="sphere" size="0.1" mass="1" group="1"/></body>
    <body pos="2 0 0.1001"><freejoint/><geom type="sphere" size="0.1" mass="1" group="1"/></body>
  </worldbody>
  <keyframe><key qvel="0 0 -1 0 0 0  0 0 -2 0 0 0  0 0 -3 0 0 0"/></keyframe>
  <custom><text name="contactlaw:balls" data="geom1=group:1 geom2=group:2 law=hunt-crossley restitution=0.6 stiffness=1e8"/></custom>
</mujoco>)");
  EXPECT_EQ(sim.contact_model().pairs().size(), 3u);
  while (sim.time() < 0.05) sim.Step();
  const std::vector<Episode>& impacts = sim.contacts().impacts();
  ASSERT_EQ(impacts.size(), 3u);
  const double exact = ExactRebound(HysteresisCoefficient(*ParseLawName("hunt-crossley"), 0.6));
  for (const Episode& impact : impacts) {
    EXPECT_FALSE(impact.open);
    EXPECT_NEAR(impact.restitution_post(), exact, kReboundTolerance);
  }
  // numbered per tag in order of first touch: the fastest ball lands first
  EXPECT_EQ(impacts[0].index, 1);
  EXPECT_EQ(impacts[2].index, 3);
  EXPECT_NEAR(impacts[0].impact_velocity, 3.0, 1e-12);  // no force before touch
}

// The scenes of mjcf/, each loaded and run.
class SceneTest : public testing::MujocoTest {
 protected:
  Simulation& LoadScene(const std::string& file, const SimulationOptions& options = {}) {
    return MakeSceneSimulation(file, options);
  }
};

TEST_F(SceneTest, AResetGivesTheRunItsOwnTimestepBack) {
  // a step of another length (the auto timestep's, the settling
  // relaxation's) is the run's until a reset: a settled run, or a replay's
  // trajectory after its settling, went on at the relaxation's last step
  SimulationOptions options;
  options.timestep = 2e-3;
  Simulation& sim = LoadScene("bouncing_ball.xml", options);
  sim.Step(1e-4);
  sim.Step();
  EXPECT_DOUBLE_EQ(sim.time(), 2e-4);
  sim.Reset();
  sim.Step();
  EXPECT_DOUBLE_EQ(sim.time(), 2e-3);
}

TEST_F(SceneTest, BouncingBallIsThePapers) {
  Simulation& sim = LoadScene("bouncing_ball.xml");
  const mjModel* m = sim.model();
  const int ball = mj_name2id(m, mjOBJ_BODY, "ball");
  EXPECT_DOUBLE_EQ(m->body_mass[ball], 1.0);
  EXPECT_DOUBLE_EQ(m->body_inertia[3 * ball], 0.1);
  EXPECT_DOUBLE_EQ(m->geom_size[3 * mj_name2id(m, mjOBJ_GEOM, "ball")], 0.1);
  EXPECT_DOUBLE_EQ(sim.data()->qpos[2], 1.0);
  EXPECT_DOUBLE_EQ(m->opt.timestep, 1e-5);
  const GeomPair& pair = sim.contact_model().pairs().at(0);
  EXPECT_EQ(pair.params.law, *ParseLawName("flores"));
  EXPECT_EQ(pair.params.restitution, 0.9);
  EXPECT_EQ(pair.params.stiffness, 1.4e8);
  EXPECT_EQ(pair.params.exponent, 1.5);

  // it falls 0.9 m and rebounds as the closed form says, up to gravity:
  // during a contact of duration tau, gravity shifts e_post by at most
  // g tau / v0 (~3e-3 here)
  const Episode impact = testing::FirstImpact(sim, 1.0);
  // the first state in contact is up to one step past the touch: g h = 1e-4
  EXPECT_NEAR(impact.impact_velocity, std::sqrt(2 * 9.81 * 0.9), 2e-4);
  const double tau = impact.time_separation - impact.time_contact;
  // the Hertz duration 2.94 delta_max / v0 = 1.33 ms, lengthened by damping
  EXPECT_NEAR(tau, 1.3e-3, 0.2e-3);
  EXPECT_NEAR(impact.restitution_post(),
              ExactRebound(HysteresisCoefficient(*ParseLawName("flores"), 0.9)),
              9.81 * tau / impact.impact_velocity);
}

TEST_F(SceneTest, BallTableRunsWithItsDrive) {
  for (const char* integrator : {"euler", "rk4"}) {
    SimulationOptions options;
    options.integrator = std::string(integrator) == "rk4" ? mjINT_RK4 : mjINT_EULER;
    options.timestep = 2e-5;
    Simulation& sim = LoadScene("ball_table.xml", options);
    ASSERT_EQ(sim.contact_model().drives().size(), 1u);
    std::vector<double> row;
    const std::vector<std::string> columns = sim.Columns();
    const auto column = [&](const char* name) {
      return std::find(columns.begin(), columns.end(), name) - columns.begin();
    };
    while (sim.time() < 1.5) {
      sim.Step();
      if (std::fmod(sim.time(), 0.1) < 2e-5) {
        sim.Sample(&row);
        // the hook places the table from d->time alone: exact but for the
        // rounding of sin and of the accumulated time (~1e-15)
        EXPECT_NEAR(row[column("table.z")], 0.5 + 0.1 * std::sin(7.5 * sim.time()), 1e-12);
        EXPECT_GT(row[column("ball.z")] - row[column("table.z")], 0.09) << "the ball stays above";
      }
    }
    EXPECT_GE(sim.contacts().impacts().size(), 2u) << integrator;
  }
}

}  // namespace
}  // namespace contactlaws
