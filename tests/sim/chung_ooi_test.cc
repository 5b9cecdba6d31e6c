// Copyright contactlaws authors.
//
// The contact benchmark of H. Chung, J. Y. Ooi, "Benchmark tests for
// verifying discrete element modelling codes at particle impact level",
// Granular Matter 13:643-656 (2011), tests 3 to 8, through MuJoCo: a sphere
// (R 2.55 mm) of the test's material onto a rigid plane, a sphere of its
// size or one of 5 times its radius, tagged with its materials: the pair
// takes Mindlin's no-slip spring 8 G* a with its Coulomb cap and the normal
// law's damping ratio (friction.h). Gravity off.
//
// Two references: the benchmark's own (chung_ooi_reference.h: the paper's
// curves, tests 4 to 8, and one DEM code's results), and the model its DEM
// codes share (Hertz normal, Mindlin's incremental no-slip spring capped at
// mu F_n, the unloading correction of Thornton et al. 2011) integrated on
// its own at 1/20000 of the contact (chung_ooi_model.h), with the rigid-body
// closed forms. The quantities are those the benchmark plots, normalized as
// it does: the tangential restitution v_t'/v_t, the spin w' R / v, and the
// contact surface's rebound angle against the incident one, Psi = 2 (1 -
// nu) / (mu (2 - nu)) x tangent (Maw, Barber, Fawcett 1976).

#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contactlaws/law.h"
#include "contactlaws/simulation.h"
#include "chung_ooi_model.h"
#include "chung_ooi_reference.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

using namespace chung_ooi;  // NOLINT: the test reads in the model's terms

// The impact's MJCF: B (and A when a sphere) with its initial velocities,
// the pair tagged with its materials, law=exact at the case's e.
std::string Scene(const ImpactCase& c, double timestep) {
  const Material& m = c.material;
  const bool plane = std::isinf(c.ra);
  const double za = 0;
  const double zb = (plane ? 0 : c.ra) + kRadius + kGap;
  // A moves the other way with B's momentum (a sphere)
  const double share = Share(c);
  const std::string a =
      plane ? R"(<geom name="a" type="plane" size="1 1 0.1"/>)"
            : fmt::format(R"(<body name="a" pos="0 0 {}"><freejoint/>
      <geom name="a" type="sphere" size="{}" density="{}"/></body>)",
                          za, c.ra, c.a_denser * m.density);
  const std::string qpos_a = plane ? "" : fmt::format("0 0 {} 1 0 0 0 ", za);
  const std::string qvel_a =
      plane ? "" : fmt::format("{} 0 {} 0 {} 0 ", -share * c.vt, share * c.vn, c.wa);
  return fmt::format(R"(<mujoco>
  <option timestep="{0}" integrator="RK4" gravity="0 0 0"/>
  <worldbody>
    {1}
    <body name="b" pos="0 0 {2}"><freejoint/>
      <geom name="b" type="sphere" size="{3}" density="{4}"/></body>
  </worldbody>
  <keyframe><key qpos="{5}0 0 {2} 1 0 0 0" qvel="{6}{7} 0 {8} 0 {9} 0"/></keyframe>
  <custom><text name="contactlaw:impact" data="geom1=b geom2=a law=exact restitution={10}
    youngs1={11} poisson1={12} youngs2={13} poisson2={12} mu={14}"/></custom>
</mujoco>)",
                     timestep, a, zb, kRadius, m.density, qpos_a, qvel_a, c.vt, -c.vn, c.w, c.e,
                     m.youngs, m.poisson, YoungsA(c), c.mu);
}

class ChungOoiTest : public testing::MujocoTest {
 protected:
  // The impact through MuJoCo, at t_c / 500 (RK4), until well apart.
  Rebound Simulate(const ImpactCase& c) {
    const double tc = ContactDuration(c);
    Simulation& sim = MakeSimulation(Scene(c, tc / 500));
    const bool plane = std::isinf(c.ra);
    const double end = kGap / c.vn + 2 * tc;
    while (sim.time() < end) sim.Step();
    const mjtNum* v = sim.data()->qvel + (plane ? 0 : 6);
    return {v[0], v[2], v[4], plane ? 0.0 : sim.data()->qvel[4]};
  }

  // The simulated rebound against the reference, and against the closed
  // form (`closed_form`, else gross sliding's where the case slides
  // throughout), in the benchmark's normalized quantities. The bound, 2%: of
  // the tangential impulse and the spin change of gross sliding (mu J / m,
  // R mu J / I: the largest friction can make), of the normalized incident
  // angle (at least 0.02) for the rebound angle, and of e for the normal
  // restitution. Returns the largest deviation, over its bound.
  double Expect(const ImpactCase& c, const char* label,
                std::optional<Rebound> closed_form = std::nullopt) {
    const Quantities sim = Measure(c, Simulate(c));
    last_ = sim;
    const Quantities ref = Measure(c, ReferenceImpact(c));
    const double j = (1 + c.e) * NormalMass(c) * c.vn * (1 + Share(c));
    const double dv = c.mu * j / Mass(c.material, kRadius);
    const double dw = kRadius * c.mu * j / Inertia(c.material, kRadius);
    const double psi_in = Normalized(c, sim.tangent_in);
    const double angle_bound = kBound * std::max(1.0, std::abs(psi_in));
    double worst = 0;
    auto check = [&](const Quantities& want, const char* against) {
      const double errors[] = {std::abs(sim.vt - want.vt) / (kBound * dv),
                               std::abs(sim.w - want.w) / (kBound * dw),
                               std::abs(Normalized(c, sim.tangent_out - want.tangent_out)) / angle_bound,
                               std::abs(sim.restitution - want.restitution) / (kBound * c.e)};
      for (double error : errors) {
        EXPECT_LE(error, 1) << label << " against " << against << ": Psi_in " << psi_in
                            << ", vt' " << sim.vt << " for " << want.vt << ", w' " << sim.w
                            << " for " << want.w << ", Psi_out " << Normalized(c, sim.tangent_out)
                            << " for " << Normalized(c, want.tangent_out) << ", e "
                            << sim.restitution << " for " << want.restitution;
        worst = std::max(worst, error);
      }
    };
    check(ref, "the reference");
    if (!closed_form) closed_form = SlidingRebound(c);
    if (closed_form) check(Measure(c, *closed_form), "the closed form");
    std::printf("%s: %s Psi_in %7.3f Psi_out %7.3f (ref %7.3f) vt' %8.4f (ref %8.4f) w' %9.2f "
                "(ref %9.2f) e %.5f\n",
                label, c.material.name, psi_in, Normalized(c, sim.tangent_out),
                Normalized(c, ref.tangent_out), sim.vt, ref.vt, sim.w, ref.w, sim.restitution);
    return worst;
  }

  // Tests 6 and 8: c at v_n 0.2 m/s, mu 0.4, e 0.5, its contact point slipping
  // at v_t,c = kSliding v_n / x, against the model (Expect), and the paper's
  // beta = -v_t,c' / v_t,c at p where the rigid sphere slides throughout (x
  // <= 1, beta = x - 1) within 2% of beta's scale 1; beyond, printed, not
  // held (docs/friction.md). Returns the largest deviation, over its bound.
  static constexpr double kSpinMu = 0.4, kSpinE = 0.5, kSliding = 3.5 * kSpinMu * (1 + kSpinE);
  double ExpectBeta(ImpactCase c, const testing::FigurePoint& p, const char* label) {
    c.mu = kSpinMu;
    c.e = kSpinE;
    c.vn = 0.2;
    c.w = -kSliding * c.vn / p.x / kRadius;
    const double worst = Expect(c, label);
    const double beta = -last_.tangent_out * last_.restitution / last_.tangent_in;
    const bool held = p.x <= 1;
    std::printf("%s against the paper, beta at x %.3f: %.4f for %.4f%s\n", label, p.x, beta, p.y,
                held ? "" : " (not held)");
    if (!held) return worst;
    const double error = std::abs(beta - p.y) / kBound;
    EXPECT_LE(error, 1) << label << ", " << c.material.name << ", beta at x " << p.x << ": "
                        << beta << " for " << p.y;
    return std::max(worst, error);
  }

  static constexpr double kBound = 0.02;  // the issue's 2%, in the units above
  Quantities last_;  // the simulated quantities of the last Expect
};

constexpr Material kMaterials[] = {kAlumina, kAlloy};

// Test 3: normal impacts at restitutions 0.1 ... 1 rebound at e (law=exact).
TEST_F(ChungOoiTest, Test3NormalImpactReboundsAtTheRestitution) {
  double worst = 0;  // the largest deviation, over its bound
  for (const Material& m : kMaterials) {
    for (double e : {0.1, 0.3, 0.5, 0.7, 0.9, 1.0}) {
      ImpactCase c{m};
      c.e = e;
      worst = std::max(worst, Expect(c, "test 3"));
    }
  }
  std::printf("test 3: largest deviation %.3f of the bound\n", worst);
}

// Test 4: 3.9 m/s at 5 ... 85 degrees from the normal, mu 0.092, e 0.98
// (Kharaz, Gorham, Salman 2001, as the benchmark gives them): the tangential
// restitution v_t'/v_t within 0.02 of the reference's besides the above.
TEST_F(ChungOoiTest, Test4ObliqueImpactAtConstantSpeed) {
  double worst = 0;  // the largest deviation, over its bound
  for (const Material& m : kMaterials) {
    for (int degrees = 5; degrees < 90; degrees += 10) {
      const ImpactCase c = Test4Impact(m, degrees);
      worst = std::max(worst, Expect(c, fmt::format("test 4 at {} deg", degrees).c_str()));
      const double et = last_.vt / c.vt;  // the simulation Expect ran
      const double reference = ReferenceImpact(c).vt / c.vt;
      EXPECT_NEAR(et, reference, kBound) << m.name << " at " << degrees << " degrees";
      std::printf("test 4: %s at %d deg: e_t %.4f (ref %.4f)\n", m.name, degrees, et, reference);
    }
  }
  std::printf("test 4: largest deviation %.3f of the bound\n", worst);
}

// Test 4 against the benchmark's own reference (chung_ooi_reference.h): the
// paper's DEM-code curves of v_t'/v_t and the spin, both materials, and one
// DEM code's (Kratos') results, alumina, 5 ... 85 degrees. The spin is
// compared as w' R (the reference's at its R; Hertz-Mindlin's normalized
// rebound does not depend on R). Bounds, 2%: of v_t'/v_t; of the curve's
// largest w' R for the spin. The paper's curves are held from 15 (v_t'/v_t)
// and 20 degrees (the spin) on: below, read off a slope of up to 0.05 per
// degree, they part from the DEM code's results, which the simulation holds.
TEST_F(ChungOoiTest, Test4AgainstThePublishedCurves) {
  constexpr double kRatio = kRadius / testing::kChungOoiTest4Radius;
  auto rebound = [&](const Material& m, double degrees) {
    const ImpactCase c = Test4Impact(m, degrees);
    const Rebound r = Simulate(c);
    return std::pair{r.vt / c.vt, std::abs(r.w) * kRatio};  // e_t; w' at the reference's R
  };
  double worst = 0;  // the largest deviation, over its bound
  auto check = [&](double got, double want, double scale, const std::string& what) {
    const double error = std::abs(got - want) / (kBound * scale);
    EXPECT_LE(error, 1) << what << ": " << got << " for " << want;
    worst = std::max(worst, error);
    std::printf("test 4 against %s: %.4f for %.4f (%+.2f%%)\n", what.c_str(), got, want,
                100 * (got - want) / want);
  };
  double peak = 0;  // the spin's scale
  for (const testing::KratosPoint& p : testing::kTest4KratosAlumina) peak = std::max(peak, p.spin);
  for (const testing::KratosPoint& p : testing::kTest4KratosAlumina) {
    const auto [et, w] = rebound(kAlumina, p.degrees);
    check(et, p.restitution, p.restitution, fmt::format("Kratos, e_t at {} deg", p.degrees));
    check(w, p.spin, peak, fmt::format("Kratos, spin at {} deg", p.degrees));
  }
  struct Curves {
    Material material;
    const testing::CurvePoint *restitution, *spin;
  };
  for (const Curves& curve :
       {Curves{kAlumina, testing::kTest4TangentialRestitutionAlumina, testing::kTest4SpinAlumina},
        Curves{kAlloy, testing::kTest4TangentialRestitutionAlloy, testing::kTest4SpinAlloy}}) {
    constexpr int kPoints = std::size(testing::kTest4SpinAlumina);
    double curve_peak = 0;
    for (int i = 0; i < kPoints; ++i) curve_peak = std::max(curve_peak, curve.spin[i].value);
    for (int i = 0; i < kPoints; ++i) {
      const testing::CurvePoint& r = curve.restitution[i];
      const testing::CurvePoint& s = curve.spin[i];
      if (r.degrees >= 14.9) {
        check(rebound(curve.material, r.degrees).first, r.value, r.value,
              fmt::format("the paper, {} e_t at {:.2f} deg", curve.material.name, r.degrees));
      }
      if (s.degrees >= 19.9) {
        check(rebound(curve.material, s.degrees).second, s.value, curve_peak,
              fmt::format("the paper, {} spin at {:.2f} deg", curve.material.name, s.degrees));
      }
    }
  }
  std::printf("test 4 against the published: largest deviation %.3f of the bound\n", worst);
}

// Test 5 with the paper's inputs (chung_ooi_reference.h): steel and
// polyethylene onto the rigid plane at v_n 5 m/s, mu 0.3, e 1, no spin, v_t
// for x = v_t / (mu v_n), against the model (Expect), and against the
// paper's curves where the rigid sphere slides throughout (x >= 3.5 (1 + e)
// = 7): v_t,c' / (mu v_n') within 2% of x, R w' / (mu v_n) within 2% of its
// 5/2 (1 + e) = 5. Below, the curves reverse the contact point where this
// model rebounds it forward: they are another spring (chung_ooi_model_test);
// printed, not held (docs/friction.md).
TEST_F(ChungOoiTest, Test5ConstantNormalVelocityVaryingTangential) {
  double worst = 0;  // the largest deviation, over its bound
  constexpr double kFrom = 3.5 * (1 + 1.0);  // x of gross sliding at e 1
  // one curve from x = from_x on; spin: R w'/(mu v_n), else v_t,c'/(mu v_n')
  auto run = [&](const Material& m, const auto& curve, bool spin, double from_x) {
    for (const testing::FigurePoint& p : curve) {
      if (p.x < from_x) continue;
      ImpactCase c{m};
      c.mu = 0.3;
      c.e = 1;
      c.vn = 5;
      c.vt = p.x * c.mu * c.vn;
      worst = std::max(worst, Expect(c, "test 5"));
      const double got = spin ? last_.w * kRadius / (c.mu * c.vn) : last_.tangent_out / c.mu;
      const bool held = p.x >= kFrom;
      std::printf("test 5 against the paper, %s at x %.3f: %.4f for %.4f%s\n",
                  spin ? "R w'/(mu v_n)" : "v_t,c'/(mu v_n')", p.x, got, p.y,
                  held ? "" : " (not held)");
      if (!held) continue;
      const double error = std::abs(got - p.y) / (kBound * (spin ? 5.0 : p.x));
      EXPECT_LE(error, 1) << m.name << (spin ? " spin" : " rebound") << " at x " << p.x << ": "
                          << got << " for " << p.y;
      worst = std::max(worst, error);
    }
  };
  run(kSteel, testing::kTest5ReboundSteel, /*spin=*/false, 0);
  run(kSteel, testing::kTest5SpinSteel, /*spin=*/true, 0);  // polyethylene where held:
  run(kPolyethylene, testing::kTest5ReboundPolyethylene, /*spin=*/false, kFrom);
  run(kPolyethylene, testing::kTest5SpinPolyethylene, /*spin=*/true, kFrom);
  std::printf("test 5: largest deviation %.3f of the bound\n", worst);
}

// Test 6 with the paper's inputs: aluminium alloy and nylon onto the rigid
// plane (ExpectBeta). Beyond gross sliding the paper's beta falls to -0.34
// (x 24), where this model's tangential damper leaves +0.02.
TEST_F(ChungOoiTest, Test6ConstantNormalVelocityVaryingSpin) {
  double worst = 0;  // the largest deviation, over its bound
  for (const testing::FigurePoint& p : testing::kTest6BetaAlloy) {
    worst = std::max(worst, ExpectBeta(ImpactCase{kAlloy}, p, "test 6"));
  }
  // nylon's curve of y = v_t,c'/v_n' against t = v_t,c/v_n, as beta = -e y / t at x =
  // kSliding / t, where held (x <= 1)
  for (const testing::FigurePoint& q : testing::kTest6ReboundTangentNylon) {
    if (q.x < kSliding) continue;
    const testing::FigurePoint p{kSliding / q.x, -kSpinE * q.y / q.x};
    worst = std::max(worst, ExpectBeta(ImpactCase{kNylon}, p, "test 6 (nylon)"));
  }
  std::printf("test 6: largest deviation %.3f of the bound\n", worst);
}

// Test 7 with the paper's inputs (Kratos', LIGGGHTS-PFM's, PySPH's scenes):
// two equal spheres, alloy or copper, each at 0.2 m/s, mu 0.4, e 0.5,
// spinning in opposite senses at w R = v tan 5, 45, 85 degrees: the surfaces
// meet at one speed, and the answer is v_t' = 0, w' = w (Kratos' curves;
// docs/friction.md). Spinning in one sense (not the paper's) they slip.
TEST_F(ChungOoiTest, Test7TwoEqualSpheresSpinningOppositely) {
  double worst = 0;  // the largest deviation, over its bound
  for (const Material& m : {kAlloy, kCopper}) {
    for (int degrees = 5; degrees < 90; degrees += 40) {
      for (const double sense : {-1.0, 1.0}) {  // A's spin over B's
        ImpactCase c{m};
        c.mu = kSpinMu;
        c.e = kSpinE;
        c.vn = 0.2;
        c.ra = kRadius;
        c.w = c.vn / kRadius * std::tan(degrees * M_PI / 180);
        c.wa = sense * c.w;
        const std::string label =
            fmt::format("test 7 at {} deg{}", degrees, sense > 0 ? ", one sense" : "");
        std::optional<Rebound> unchanged;
        if (sense < 0) unchanged = Rebound{0, c.e * c.vn, c.w, c.wa};
        worst = std::max(worst, Expect(c, label.c_str(), unchanged));
      }
    }
  }
  std::printf("test 7: largest deviation %.3f of the bound\n", worst);
}

// Test 8 with the paper's inputs (the same scenes): test 6's impact onto a
// resting sphere of 5 times the radius and 1000 times the density, 1000
// times stiffer (case A) or of one material (case B), alloy and nylon,
// against both cases' curves (chung_ooi_reference.h; ExpectBeta).
TEST_F(ChungOoiTest, Test8SphereOntoASphereFiveTimesLarger) {
  double worst = 0;  // the largest deviation, over its bound
  for (const Material& m : {kAlloy, kNylon}) {
    for (const bool case_a : {true, false}) {
      const auto& curve = case_a ? testing::kTest8BetaCaseA : testing::kTest8BetaCaseB;
      for (const int i : {1, 4, 16}) {  // x 0.36, 0.98 and 24: test 6 runs the turn
        const testing::FigurePoint& p = curve[i];
        ImpactCase c{m};
        c.ra = 5 * kRadius;
        c.a_denser = 1000;
        c.a_stiffer = case_a ? 1000 : 1;
        worst = std::max(worst, ExpectBeta(c, p, case_a ? "test 8 (case A)" : "test 8 (case B)"));
      }
    }
  }
  std::printf("test 8: largest deviation %.3f of the bound\n", worst);
}

// The ledger through a tangential rebound (test 5's elastic impact at Psi
// 1, where the surface sticks and its spring gives back what it stored):
// the total is the start's, and the kinetic energy comes back but for what
// slid at the cap as the load fell (the dissipated share).
TEST_F(ChungOoiTest, TheLedgerBalancesThroughATangentialRebound) {
  ImpactCase c{kAlumina};
  c.e = 1;
  c.vn = 5;
  const double nu = c.material.poisson;
  c.vt = c.mu * (2 - nu) / (2 * (1 - nu)) * c.vn;
  const double tc = ContactDuration(c);
  Simulation& sim = MakeSimulation(Scene(c, tc / 500));
  mj_forward(sim.model(), sim.data());
  const EnergyLedger start = sim.Energy();
  while (sim.time() < kGap / c.vn + 2 * tc) sim.Step();
  mj_forward(sim.model(), sim.data());
  const EnergyLedger end = sim.Energy();
  // RK4 at t_c / 500: the trapezoid of friction's power over a step
  constexpr double kLedgerTolerance = 1e-6;  // of the kinetic energy
  EXPECT_NEAR(end.total(), start.total(), kLedgerTolerance * start.kinetic);
  EXPECT_EQ(end.elastic, 0);
  EXPECT_NEAR(end.kinetic + end.dissipated, start.kinetic, kLedgerTolerance * start.kinetic);
  std::printf("tangential rebound: kinetic %.9g -> %.9g J, dissipated %.3g J, total %.9g -> "
              "%.9g J\n", start.kinetic, end.kinetic, end.dissipated, start.total(), end.total());
}

// mjcf/chung_ooi_oblique.xml, the scene scripts/run.sh sweeps: test 4 at 45
// degrees, which slides throughout, leaves at the rigid-body closed form.
TEST_F(ChungOoiTest, TheSceneOfTest4SlidesAt45DegreesAsTheClosedFormHasIt) {
  Simulation& sim = MakeSceneSimulation("chung_ooi_oblique.xml");
  while (sim.time() < 2e-5) sim.Step();
  ImpactCase c{kAlumina};
  c.vn = c.vt = 3.9 * std::sqrt(0.5);
  const Rebound sliding = *SlidingRebound(c);
  // the lever R - d/2 of the spin (d up to 6.3 um: 0.12% of R)
  constexpr double kLeverShare = 2e-3;  // relative
  // law=exact rebounds at e to 1e-5 (check: e_post 0.980008), which moves
  // v_t' by mu v_n 1e-5 = 2.5e-6 m/s at most
  constexpr double kRestitutionShare = 1e-5;
  EXPECT_NEAR(sim.data()->qvel[0], sliding.vt, kRestitutionShare * c.mu * c.vn);
  EXPECT_NEAR(sim.data()->qvel[4], sliding.w, kLeverShare * sliding.w);
  EXPECT_NEAR(sim.data()->qvel[2], sliding.vn, kRestitutionShare * c.vn);
}

}  // namespace
}  // namespace contactlaws
