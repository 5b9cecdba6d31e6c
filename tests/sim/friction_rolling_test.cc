// Copyright contactlaws authors.
//
// Friction on a rolling sphere against closed forms, beside friction_test.cc:
// the backspin case of sliding to rolling in the form, a sphere on an
// incline steeper than 7/2 mu (it slides), and an oblique impact below the
// gross-sliding limit (it leaves rolling). Scenes: friction_scenes.h.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"
#include "sim/friction_scenes.h"

namespace contactlaws {
namespace {

class FrictionRollingTest : public testing::MujocoTest {};

using testing::FrictionScene;
using testing::Incline;
using testing::kG;
using testing::kRadius;
using testing::Lever;
using testing::RunUntil;
using testing::StaticDepth;
using testing::Vx;
using testing::Wy;

// A ball launched at v0 with backspin w0 (spinning against its motion)
// rolls at (5 v0 - 2 R w0) / 7 from t = 2 (v0 + R w0) / (7 mu g).
TEST_F(FrictionRollingTest, BackspinRollsAtFiveV0LessTwoRW0OverSeven) {
  constexpr double kMu = 0.3;
  constexpr double kV0 = 2.0;
  constexpr double kBackspin = 5.0;  // rad/s: the ball spins about -y
  Simulation& sim = MakeSimulation(FrictionScene(
      true, 0, kG, fmt::format("{} 0 0 0 {} 0", kV0, -kBackspin), fmt::format("mu={}", kMu)));
  const double rolling = (5 * kV0 - 2 * kRadius * kBackspin) / 7;
  const double t_roll = 2 * (kV0 + kRadius * kBackspin) / (7 * kMu * kG);
  // the contact point sits at R - d/2 (d = 0.46 mm), not R: the closed forms
  // with R are off by the depth's share of the lever, d / (2R) = 0.23%, of
  // the speeds (3.3e-3 m/s here) and of the time
  const double lever_share = 0.5 * StaticDepth(kG) / kRadius;
  RunUntil(sim, (1 - 2 * lever_share) * t_roll - 0.01);
  EXPECT_GT(Vx(sim) - Wy(sim) * Lever(kG), 0.01) << "rolls before t_roll";
  // rolling from t_roll: the stick spring catches the slip, overshoots and
  // relaxes (the slip: 4.3e-3 m/s 10 ms after t_roll)
  constexpr double kCatchTime = 3e-2;   // s
  constexpr double kCaughtSlip = 1e-3;  // m/s, measured 7.4e-4 at kCatchTime
  RunUntil(sim, (1 + 2 * lever_share) * t_roll + kCatchTime);
  EXPECT_NEAR(Vx(sim) - Wy(sim) * Lever(kG), 0, kCaughtSlip);
  std::printf("backspin: slip %.3g m/s at t_roll + %g s\n", Vx(sim) - Wy(sim) * Lever(kG),
              kCatchTime);
  // and it rolls on at the closed form's speed, without slip (measured
  // 4e-7 m/s: the stick spring's stretch)
  constexpr double kRollingSlip = 1e-5;  // m/s
  RunUntil(sim, t_roll + 0.2);
  EXPECT_NEAR(Vx(sim), rolling, lever_share * kV0);
  EXPECT_NEAR(Wy(sim) * kRadius, rolling, lever_share * kV0);
  EXPECT_NEAR(Vx(sim) - Wy(sim) * Lever(kG), 0, kRollingSlip);
  std::printf("backspin: v %.5f, w R %.5f (%.5f), slip %.3g m/s\n", Vx(sim),
              Wy(sim) * kRadius, rolling, Vx(sim) - Wy(sim) * Lever(kG));
}

// tan(theta) = 0.5 > 7/2 mu = 0.35: the friction cannot make the sphere roll.
// It slides, its centre at g (sin - mu cos), its spin at 5/2 mu g cos / R.
TEST_F(FrictionRollingTest, SphereSteeperThanSevenHalvesMuSlides) {
  constexpr double kTan = 0.5;
  constexpr double kMu = 0.1;
  Simulation& sim = MakeSimulation(Incline(true, kTan, fmt::format("mu={}", kMu)));
  RunUntil(sim, 0.2);
  const double v1 = Vx(sim);
  const double w1 = Wy(sim);
  RunUntil(sim, 0.5);
  const double c = 1 / std::sqrt(1 + kTan * kTan);
  const double a = kG * (kTan * c - kMu * c);
  const double alpha_r = 2.5 * kMu * kG * c;
  // sliding friction is mu F_n whatever the lever: the centre's acceleration
  // measured within 1e-6; the spin's torque has the lever R - d/2 (measured
  // 0.21% short)
  constexpr double kAccelerationTolerance = 5e-3;  // relative
  EXPECT_NEAR((Vx(sim) - v1) / 0.3, a, kAccelerationTolerance * a);
  EXPECT_NEAR((Wy(sim) - w1) / 0.3 * kRadius, alpha_r, kAccelerationTolerance * alpha_r);
  EXPECT_GT(Vx(sim) - Wy(sim) * kRadius, 0.1) << "slides";
  std::printf("sliding sphere: a %.5f (%.5f), alpha R %.5f (%.5f)\n", (Vx(sim) - v1) / 0.3, a,
              (Wy(sim) - w1) / 0.3 * kRadius, alpha_r);
}

// An oblique impact below the gross-sliding limit, v_t < 7/2 mu (1 + e) v_n:
// friction stops the slip during the contact, and a rigid ball would leave
// rolling at v' = w' R = 5/7 v_t (its angular momentum about the contact
// point, m R (v + 2/5 w R), is kept). A compliant contact gives part of its
// stick spring's energy back as the normal load falls, so the slip comes out
// small and reversed (tangential restitution, Maw, Barber, Fawcett 1976).
TEST_F(FrictionRollingTest, ObliqueImpactBelowTheSlidingLimitLeavesRolling) {
  constexpr double kMu = 0.2;
  constexpr double kVt = 0.3;  // m/s, < 7/2 mu (1 + e) v_n = 1.05 at e = 0.5
  Simulation& sim = MakeSimulation(testing::ObliqueImpact(kVt, kMu));
  while (sim.contacts().impacts().empty() || sim.contacts().impacts()[0].open) sim.Step();
  const Episode& impact = sim.contacts().impacts()[0];
  const double e = impact.restitution_post();
  ASSERT_LT(kVt, 3.5 * kMu * (1 + e) * 1.0) << "not below the sliding limit";
  const double v = Vx(sim);
  const double wr = Wy(sim) * kRadius;
  // the angular momentum about the contact point: the normal force passes
  // through the centre, the friction through the point (the lever R - d/2
  // at up to 4% depth: measured 0.4% short)
  constexpr double kMomentumTolerance = 1e-2;  // relative
  EXPECT_NEAR(v + 0.4 * wr, kVt, kMomentumTolerance * kVt);
  // rolling, to the stick spring's give-back: measured slip -0.07 v_t (a
  // sliding exit would keep a slip of the order of v_t)
  constexpr double kExitSlip = 0.1;  // of v_t
  EXPECT_LT(std::abs(v - wr), kExitSlip * kVt);
  EXPECT_LT(impact.tangential_restitution(), kExitSlip);
  // hence both near 5/7 v_t, within 2/7 and 5/7 of that slip
  EXPECT_NEAR(v, 5.0 / 7.0 * kVt, 2.0 / 7.0 * kExitSlip * kVt);
  EXPECT_NEAR(wr, 5.0 / 7.0 * kVt, 5.0 / 7.0 * kExitSlip * kVt);
  std::printf("below the limit: e %.4f, vt' %.5f, w'R %.5f (5/7 vt %.5f), e_t %.4f\n", e, v,
              wr, 5.0 / 7.0 * kVt, impact.tangential_restitution());
}

}  // namespace
}  // namespace contactlaws
