// Copyright contactlaws authors.
//
// The friction kernels alone, against their formulas.

#include "contactlaws/friction.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace contactlaws {
namespace {

FrictionParams Params(FrictionKind kind) {
  FrictionParams p;
  p.kind = kind;
  p.mu_static = 0.5;
  p.mu_kinetic = 0.3;
  return p;
}

TEST(FrictionKernelTest, CoulombSticksWithoutCreepInsideTheLimitAndSlidesAtTheKineticCap) {
  const FrictionParams p = Params(FrictionKind::kCoulomb);
  FrictionInput in;
  in.normal_force = 10;
  in.stiffness = in.committed_stiffness = 1e4;
  in.committed[0] = -2;   // holds 2 N against a slip along +x
  in.stretch[0] = 1e-4;   // 1 N more
  const FrictionOutput stick = EvaluateFriction(p, in);
  EXPECT_FALSE(stick.sliding);
  EXPECT_DOUBLE_EQ(stick.force[0], -3);  // the spring: no velocity needed to hold
  EXPECT_DOUBLE_EQ(stick.stored_energy, 9 / 2e4);
  // beyond mu_s F_n = 5 N: slides, at the cap along the spring, then mu_k
  in.stretch[0] = 1e-3;
  const FrictionOutput slip = EvaluateFriction(p, in);
  EXPECT_TRUE(slip.sliding);
  EXPECT_DOUBLE_EQ(slip.force[0], -5);
  in.was_sliding = true;
  in.slip[0] = 0.1;
  const FrictionOutput slide = EvaluateFriction(p, in);
  EXPECT_DOUBLE_EQ(slide.force[0], -3);
}

// The ledger counts as dissipated what the bodies lose less what the springs
// hold (contact_memory.h): sound only if no update of the spring's state
// makes energy. With no stretch, whatever the stiffness and the caps do, the
// spring holds at most the energy it was committed with; with a stretch, at
// most the energy of the uncapped elastic path.
TEST(FrictionKernelTest, TheStickSpringNeverHoldsEnergyItWasNotGiven) {
  // relative, for the rounding of |F|^2 / 2k
  constexpr double kRoundingTolerance = 1e-12;
  unsigned state = 12345;
  auto uniform = [&state](double lo, double hi) {
    state = state * 1664525u + 1013904223u;  // a fixed sequence: the test repeats
    return lo + (hi - lo) * (state >> 8) / double(1u << 24);
  };
  for (int trial = 0; trial < 2000; ++trial) {
    CappedSpringInput in;
    for (int i = 0; i < 3; ++i) in.committed[i] = uniform(-10, 10);
    in.committed_stiffness = uniform(1e3, 1e6);
    in.stiffness = uniform(1e3, 1e6);
    in.stick_limit = uniform(0, 20);
    in.slide_limit = uniform(0, in.stick_limit);
    in.was_sliding = trial % 2 == 0;
    const double committed_energy =
        (in.committed[0] * in.committed[0] + in.committed[1] * in.committed[1] +
         in.committed[2] * in.committed[2]) / (2 * in.committed_stiffness);
    const double held = CappedSpring(in).stored_energy;
    EXPECT_LE(held, committed_energy * (1 + kRoundingTolerance)) << "trial " << trial;

    for (int i = 0; i < 3; ++i) in.stretch[i] = uniform(-1e-4, 1e-4);
    const double scale = std::min(1.0, in.stiffness / in.committed_stiffness);
    double elastic = 0;
    for (int i = 0; i < 3; ++i) {
      const double f = in.committed[i] * scale - in.stiffness * in.stretch[i];
      elastic += f * f / (2 * in.stiffness);
    }
    EXPECT_LE(CappedSpring(in).stored_energy, elastic * (1 + kRoundingTolerance))
        << "trial " << trial;
  }
}

TEST(FrictionKernelTest, RegularizedCreepsAtTheSpeedItsCurveGivesTheLoad) {
  const FrictionParams p = Params(FrictionKind::kRegularized);
  FrictionInput in;
  in.normal_force = 10;
  // a load of 60% of mu_s F_n is carried at s (2 - s) = 0.6: s = 1 - sqrt(0.4)
  const double s = 1 - std::sqrt(0.4);
  in.slip[1] = s * p.transition_velocity;
  EXPECT_NEAR(EvaluateFriction(p, in).force[1], -3, 1e-12);
  in.slip[1] = 3 * p.transition_velocity;  // the kinetic plateau from s = 3
  EXPECT_NEAR(EvaluateFriction(p, in).force[1], -3 * 10 * 0.1, 1e-12);
}

TEST(FrictionKernelTest, StribeckFallsFromStaticToKinetic) {
  const FrictionParams p = Params(FrictionKind::kStribeck);
  EXPECT_DOUBLE_EQ(SlidingMu(p, 0), 0.5);
  EXPECT_NEAR(SlidingMu(p, p.stribeck_velocity), 0.3 + 0.2 / std::exp(1.0), 1e-15);
  EXPECT_NEAR(SlidingMu(p, 100 * p.stribeck_velocity), 0.3, 1e-15);
}

TEST(FrictionKernelTest, LuGreReachesItsSteadyStateForceAfterALongSlide) {
  FrictionParams p = Params(FrictionKind::kLuGre);
  p.viscous = 0.2;
  FrictionInput in;
  in.normal_force = 10;
  in.slip[0] = 1.0;
  in.stretch[0] = 1.0;  // 1 m: far beyond the bristles' mu/sigma0 = 5 um
  const FrictionOutput out = EvaluateFriction(p, in);
  // z = mu_k/sigma0, z' = 0: F = mu(v) F_n + sigma2 v
  EXPECT_NEAR(out.force[0], -(0.3 * 10 + 0.2), 1e-9);
  EXPECT_NEAR(out.state[0], 0.3 / p.bristle_stiffness, 1e-15);
}

// The bristle damper sigma1 z' fades with the slip speed as exp(-(v/v_s)^2)
// (Olsson et al. 1998): whole while presliding, gone in gross sliding. The
// bristles at rest (z = 0, no stretch yet) under a slip v: z' = v, and the
// force is the damper's alone.
TEST(FrictionKernelTest, LuGreBristleDamperFadesWithTheSlipSpeed) {
  const FrictionParams p = Params(FrictionKind::kLuGre);
  FrictionInput in;
  in.normal_force = 10;
  in.mass = 2;
  const double sigma1 = BristleDamping(p, in.normal_force, in.mass);
  EXPECT_DOUBLE_EQ(sigma1, 2 * std::sqrt(p.bristle_stiffness * 10 * 2));  // critical
  for (const double v : {1e-6, 0.5 * p.stribeck_velocity, p.stribeck_velocity,
                         3 * p.stribeck_velocity, 1.0}) {
    in.slip[0] = v;
    const double fade = std::exp(-(v / p.stribeck_velocity) * (v / p.stribeck_velocity));
    // one rounding in each factor
    EXPECT_NEAR(EvaluateFriction(p, in).force[0], -sigma1 * fade * v, 1e-14 * sigma1 * v) << v;
  }
  // at 1 m/s, 100 v_s: nothing (it was sigma1 v = 2.8e3 N on a 10 N load)
  EXPECT_EQ(EvaluateFriction(p, in).force[0], 0);
}

TEST(FrictionKernelTest, TheTableNamesEveryModelAndRefusesBadValues) {
  for (const FrictionInfo& model : FrictionModels()) {
    EXPECT_EQ(ParseFrictionName(model.name), model.kind);
    EXPECT_FALSE(model.reference.empty());
  }
  EXPECT_FALSE(ParseFrictionName("coulmb"));
  FrictionParams p = Params(FrictionKind::kCoulomb);
  EXPECT_FALSE(ValidateFrictionParams(p));
  p.mu_kinetic = 0.6;
  EXPECT_EQ(ValidateFrictionParams(p)->key, "mu_kinetic");
  p = Params(FrictionKind::kCoulomb);
  p.tangential_stiffness = 0;  // not read by Mindlin's rule
  EXPECT_FALSE(ValidateFrictionParams(p));
  p.stiffness_rule = TangentialStiffnessRule::kGiven;
  EXPECT_EQ(ValidateFrictionParams(p)->key, "tangential_stiffness");
  p = Params(FrictionKind::kCoulomb);
  p.tangential_ratio = -1;
  EXPECT_EQ(ValidateFrictionParams(p)->key, "tangential_ratio");
  p = Params(FrictionKind::kCoulomb);
  p.tangential_damping_ratio = 1.5;
  EXPECT_EQ(ValidateFrictionParams(p)->key, "tangential_damping_ratio");
  p.tangential_damping_ratio = 1;
  EXPECT_FALSE(ValidateFrictionParams(p));
}

// Mindlin's no-slip spring: 8 G* a of two spheres whose normal law is Hertz's
// 4/3 E* sqrt(R*) d^1.5, G* of each material's own Poisson ratio.
TEST(FrictionKernelTest, MindlinsStiffnessIsEightGStarA) {
  // rounding of a few operations
  constexpr double kRounding = 1e-14;
  const double e1 = 380e9, nu1 = 0.23, e2 = 70e9, nu2 = 0.25;  // alumina on glass
  const double r = 2.55e-3, d = 1e-6;
  const double e_star = 1 / ((1 - nu1 * nu1) / e1 + (1 - nu2 * nu2) / e2);
  const double g1 = e1 / (2 * (1 + nu1)), g2 = e2 / (2 * (1 + nu2));
  const double g_star = 1 / ((2 - nu1) / g1 + (2 - nu2) / g2);
  LawParams hertz;
  hertz.stiffness = 4.0 / 3.0 * e_star * std::sqrt(r);
  FrictionParams p = Params(FrictionKind::kCoulomb);
  p.tangential_ratio = MindlinRatio(e1, nu1, e2, nu2);
  EXPECT_NEAR(TangentialStiffness(p, hertz, d) / (8 * g_star * std::sqrt(r * d)), 1, kRounding);
  // one material: 2 (1 - nu) / (2 - nu), the default's form
  EXPECT_NEAR(MindlinRatio(2e11, kDefaultPoisson, 2e11, kDefaultPoisson), kMindlinRatio, kRounding);
  // the tag's k_t
  p.stiffness_rule = TangentialStiffnessRule::kGiven;
  p.tangential_stiffness = 5e5;
  EXPECT_EQ(TangentialStiffness(p, hertz, d), 5e5);
}

// c_t: the tag's, zeta's, the normal law's damping ratio on k_t, or critical.
TEST(FrictionKernelTest, TangentialDampingTakesTheNormalLawsDampingRatio) {
  // rounding of a few operations
  constexpr double kRounding = 1e-14;
  LawParams law;
  law.law = *ParseLawName("hunt-crossley");
  law.stiffness = 1e9;
  law.restitution = 0.9;
  ResolveLawParams(&law);
  ContactState state;
  state.depth = 1e-5;
  state.impact_velocity = 2;
  const double k_n = NormalStiffness(law, state.depth);
  const double c_n = DampingCoefficient(law, state);
  const double k_t = 0.8 * k_n, m = 0.01;
  FrictionParams p = Params(FrictionKind::kCoulomb);
  EXPECT_DOUBLE_EQ(TangentialDamping(p, law, state, k_t, m), 2 * std::sqrt(k_t * m));
  p.damping_rule = TangentialDampingRule::kNormalLaw;
  // the same ratio c / (2 sqrt(k m)) on both springs
  const double c_t = TangentialDamping(p, law, state, k_t, m);
  EXPECT_NEAR(c_t / (2 * std::sqrt(k_t * m)), c_n / (2 * std::sqrt(k_n * m)), kRounding);
  EXPECT_GT(c_t, 0);
  state.depth = 0;
  EXPECT_EQ(TangentialDamping(p, law, state, k_t, m), 0);
  p.damping_rule = TangentialDampingRule::kRatio;
  p.tangential_damping_ratio = 0.5;
  EXPECT_DOUBLE_EQ(TangentialDamping(p, law, state, k_t, m), std::sqrt(k_t * m));
  p.damping_rule = TangentialDampingRule::kGiven;
  p.tangential_damping = 3;
  EXPECT_EQ(TangentialDamping(p, law, state, k_t, m), 3);
}

// The tangential time scale: pi / omega of a critically damped stick spring,
// pi over the fastest rate of an over-damped one, pi tau of regularized's
// damper; infinite without friction or load.
TEST(FrictionKernelTest, TangentialDurationIsPiOverTheFastestRate) {
  FrictionParams p = Params(FrictionKind::kCoulomb);
  const double m = 2, k = 8e4, fn = 19.62;
  EXPECT_DOUBLE_EQ(TangentialDuration(p, k, 2 * std::sqrt(k * m), m, fn), M_PI * std::sqrt(m / k));
  // c = 10 sqrt(k m): rates of m s^2 + c s + k = 0, the larger one
  const double c = 10 * std::sqrt(k * m);
  const double half = c / (2 * m);
  EXPECT_DOUBLE_EQ(TangentialDuration(p, k, c, m, fn),
                   M_PI / (half + std::sqrt(half * half - k / m)));
  // a damper: ten lags m / c, so that 20 steps per period 2 x duration are a
  // lag each
  p = Params(FrictionKind::kRegularized);
  EXPECT_DOUBLE_EQ(TangentialDuration(p, k, 0, m, fn),
                   10 * m * p.transition_velocity / (2 * p.mu_static * fn));
  p = Params(FrictionKind::kLuGre);
  p.bristle_damping = 0;
  EXPECT_DOUBLE_EQ(TangentialDuration(p, k, 0, m, fn),
                   M_PI * std::sqrt(m / (p.bristle_stiffness * fn)));
  EXPECT_TRUE(std::isinf(TangentialDuration(p, k, 0, m, 0)));
  EXPECT_TRUE(std::isinf(TangentialDuration(Params(FrictionKind::kNone), k, 0, m, fn)));
  EXPECT_TRUE(std::isinf(TangentialDuration(Params(FrictionKind::kCoulomb), k, 0, INFINITY, fn)));
}

}  // namespace
}  // namespace contactlaws
