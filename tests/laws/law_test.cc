// Copyright contactlaws authors.
//
// The law kernels against hand-computed values: no MuJoCo here.

#include "contactlaws/law.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>


namespace contactlaws {
namespace {

// Kernel arithmetic is a few flops: agree with the hand value to rounding.
constexpr double kRoundoff = 1e-12;

LawParams Hertzian(LawId kind, double e) {
  LawParams p;
  p.law = kind;
  p.restitution = e;
  p.stiffness = 1.4e8;
  p.exponent = 1.5;
  p.dissipation = 0.2;  // s/m, read by the constant-dissipation family only
  ResolveLawParams(&p);
  return p;
}

// d = 1e-3 m, d' = 2 m/s, v0 = 4 m/s, K = 1.4e8: K d^1.5 = 1.4e8 * 3.16227766e-5
constexpr double kDepth = 1e-3;
constexpr double kRate = 2.0;
constexpr double kV0 = 4.0;
const double kHertzForce = 1.4e8 * std::pow(1e-3, 1.5);  // 4427.188724 N

double Force(const LawParams& p, double depth, double rate, double v0 = kV0,
             double m_eff = 1.0) {
  return EvaluateLaw(p, ContactState{depth, rate, v0, m_eff}).total;
}

TEST(LawTest, HertzByHand) {
  EXPECT_NEAR(kHertzForce, 4427.188724235731, 1e-6);
  EXPECT_NEAR(Force(Hertzian(*ParseLawName("hertz"), 1.0), kDepth, kRate), kHertzForce,
              kRoundoff * kHertzForce);
  // the depth rate plays no part
  EXPECT_EQ(Force(Hertzian(*ParseLawName("hertz"), 1.0), kDepth, -7.0), kHertzForce);
}

TEST(LawTest, HysteresisForceByHand) {
  // hunt-crossley at e = 0.6: a = 3 * 0.4 / 2 = 0.6; factor 1 + 0.6 * 2/4 = 1.3
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(*ParseLawName("hunt-crossley"), 0.6), 0.6);
  EXPECT_NEAR(Force(Hertzian(*ParseLawName("hunt-crossley"), 0.6), kDepth, kRate), 1.3 * kHertzForce,
              kRoundoff * kHertzForce);
}

TEST(LawTest, KelvinVoigtByHand) {
  LawParams p;
  p.law = *ParseLawName("kelvin-voigt");
  p.linear_stiffness = 5e6;
  p.restitution = 0.5;
  // zeta = ln 2 / sqrt(pi^2 + ln^2 2) = 0.6931472 / 3.2171501 = 0.2154538
  EXPECT_NEAR(KelvinVoigtDampingRatio(0.5), 0.2154538, 1e-7);
  // c = 2 zeta sqrt(5e6 * 2) = 0.430894 * 3162.2777 = 1362.6
  const double c = 2 * KelvinVoigtDampingRatio(0.5) * std::sqrt(5e6 * 2.0);
  EXPECT_NEAR(Force(p, kDepth, kRate, kV0, 2.0), 5e6 * kDepth + c * kRate, kRoundoff * 1e4);
  // explicit damping wins over the restitution
  p.damping = 100.0;
  EXPECT_NEAR(Force(p, kDepth, kRate, kV0, 2.0), 5000 + 200, kRoundoff * 1e4);
  // e = 1: no damping; e = 0: critical
  EXPECT_EQ(KelvinVoigtDampingRatio(1.0), 0.0);
  EXPECT_EQ(KelvinVoigtDampingRatio(0.0), 1.0);
}

TEST(LawTest, NoForceOutOfContact) {
  for (LawId kind : AllLaws()) {
    LawParams p = Hertzian(kind, 0.5);
    p.linear_stiffness = 5e6;
    for (double depth : {0.0, -1e-9, -1.0}) {
      const ContactForce f = EvaluateLaw(p, ContactState{depth, 3.0, kV0, 1.0});
      EXPECT_EQ(f.total, 0.0) << LawName(kind) << " at d = " << depth;
      EXPECT_EQ(f.elastic, 0.0);
      EXPECT_EQ(ElasticEnergy(p, depth), 0.0);
    }
  }
}

TEST(LawTest, HertzFamilyContinuousAtFirstTouch) {
  // F -> 0 as d -> 0+, whatever the approach speed (unlike Kelvin-Voigt):
  // every law of the table but the linear one
  for (LawId kind : AllLaws()) {
    if (Law(kind).family == LawFamily::kLinear) continue;
    const LawParams p = Hertzian(kind, 0.3);
    EXPECT_LT(Force(p, 1e-12, kV0), 1e-8) << LawName(kind);
    EXPECT_LT(Force(p, 1e-12, -kV0), 1e-8) << LawName(kind);
  }
  LawParams kv;
  kv.law = *ParseLawName("kelvin-voigt");
  kv.linear_stiffness = 5e6;
  kv.restitution = 0.3;
  EXPECT_GT(Force(kv, 1e-12, kV0, kV0, 1.0), 100.0) << "Kelvin-Voigt jumps to c v0";
}

TEST(LawTest, RestitutionOneIsHertz) {
  // every law with an a(e): a(1) = 0
  const double hertz = Force(Hertzian(*ParseLawName("hertz"), 1.0), kDepth, kRate);
  for (LawId kind : AllLaws()) {
    if (Law(kind).family != LawFamily::kHysteresis || !ReadsRestitution(kind)) continue;
    EXPECT_EQ(HysteresisCoefficient(kind, 1.0), 0.0) << LawName(kind);
    EXPECT_EQ(Force(Hertzian(kind, 1.0), kDepth, kRate), hertz) << LawName(kind);
    EXPECT_EQ(Force(Hertzian(kind, 1.0), kDepth, -kRate), hertz) << LawName(kind);
  }
}

TEST(LawTest, ClampedUnlessTensionAllowed) {
  // flores e = 0.5 (a = 1.6), separating at d' = -v0: factor 1 - 1.6 < 0
  LawParams p = Hertzian(*ParseLawName("flores"), 0.5);
  const ContactForce clamped = EvaluateLaw(p, ContactState{kDepth, -kV0, kV0, 1.0});
  EXPECT_EQ(clamped.total, 0.0);
  // the clamp removes tension only: the ledger still sees dissipation >= 0
  EXPECT_GE(clamped.dissipated_power(-kV0), 0.0);
  p.allow_tension = true;
  EXPECT_NEAR(Force(p, kDepth, -kV0), -0.6 * kHertzForce, kRoundoff * kHertzForce);
}

TEST(LawTest, ElasticEnergyIsTheSpringIntegral) {
  // K d^(n+1)/(n+1) for the Hertz family, k d^2 / 2 for Kelvin-Voigt
  EXPECT_NEAR(ElasticEnergy(Hertzian(*ParseLawName("flores"), 0.5), kDepth),
              kHertzForce * kDepth / 2.5, kRoundoff);
  LawParams kv;
  kv.law = *ParseLawName("kelvin-voigt");
  kv.linear_stiffness = 5e6;
  EXPECT_NEAR(ElasticEnergy(kv, kDepth), 2.5, kRoundoff);
}

TEST(LawTest, MaterialStiffnessByHand) {
  // steel on a plane: E = 2.1e11 Pa, nu = 0.3, R = 0.1 m
  // s = 0.91 / 2.1e11 = 4.3333e-12; K = 4 / (3 * 8.6667e-12) * sqrt(0.1)
  const double s = MaterialCompliance(2.1e11, 0.3);
  EXPECT_NEAR(s, 4.333333333e-12, 1e-20);
  EXPECT_NEAR(HertzSphereStiffness(0.1, std::numeric_limits<double>::infinity(), s, s),
              4.0 / (3.0 * 2 * s) * std::sqrt(0.1), 1.0);
  // two spheres 0.1 and 0.3: effective radius 0.075
  EXPECT_NEAR(HertzSphereStiffness(0.1, 0.3, s, s), 4.0 / (3.0 * 2 * s) * std::sqrt(0.075),
              1.0);
}

TEST(LawTest, ValidationNamesKeyValueAndRange) {
  auto error = [](LawParams p) { return ValidateLawParams(p); };
  LawParams ok = Hertzian(*ParseLawName("flores"), 0.9);
  EXPECT_FALSE(error(ok).has_value());

  LawParams p = ok;
  p.restitution = 0.0;
  ASSERT_TRUE(error(p));
  EXPECT_EQ(error(p)->key, "restitution");
  EXPECT_EQ(error(p)->requirement, "must be in (0, 1] for flores");
  p.law = *ParseLawName("hunt-crossley");  // e = 0 is fine for Hunt-Crossley
  EXPECT_FALSE(error(p).has_value());
  p.restitution = 1.5;
  EXPECT_EQ(error(p)->requirement, "must be in [0, 1]");
  EXPECT_EQ(error(p)->value, 1.5);
  p.restitution = std::nan("");
  EXPECT_EQ(error(p)->key, "restitution");

  p = ok;
  p.stiffness = -1;
  EXPECT_EQ(error(p)->key, "stiffness");
  p = ok;
  p.stiffness = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error(p)->key, "stiffness");
  p = ok;
  p.exponent = 0.5;
  EXPECT_EQ(error(p)->key, "exponent");
  p = ok;
  p.min_impact_velocity = 0;
  EXPECT_EQ(error(p)->key, "min_impact_velocity");

  LawParams kv;
  kv.law = *ParseLawName("kelvin-voigt");
  kv.restitution = 0.5;
  EXPECT_EQ(error(kv)->key, "linear_stiffness");
  kv.linear_stiffness = 1e6;
  EXPECT_FALSE(error(kv).has_value());
  kv.damping = -2;
  EXPECT_EQ(error(kv)->key, "damping");

  // a law that reads no e takes any: hunt-crossley-constant
  p = Hertzian(*ParseLawName("hunt-crossley-constant"), 0.0);
  EXPECT_FALSE(error(p).has_value());
  p.dissipation.reset();
  EXPECT_EQ(error(p)->requirement, "must be given, >= 0 (s/m), for hunt-crossley-constant");
}

TEST(LawTest, TheRestingDamperLagIsMassTimesV0OverTheHysteresisTimesTheLoad) {
  // F = K d^n (1 + a d' / v0): c = a K d^n / v0 = a W / v0 at rest under W
  constexpr double kRelativeTolerance = 1e-9;  // the finite difference of a law linear in d'
  LawParams p;
  p.law = *ParseLawName("hunt-crossley");
  p.restitution = 0.5;
  p.stiffness = 1e7;
  ResolveLawParams(&p);
  const double a = HysteresisCoefficient(p.law, p.restitution);  // 0.75
  const double m = 2, load = 19.62;
  const double expected = m * p.min_impact_velocity / (a * load);
  EXPECT_NEAR(RestingDamperLag(p, load, m), expected, kRelativeTolerance * expected);
  // however the load is shared: half the load, twice the lag of that point
  EXPECT_NEAR(RestingDamperLag(p, load / 2, m), 2 * expected, kRelativeTolerance * expected);
  // a larger floor, a longer lag
  p.min_impact_velocity = 1e-2;
  EXPECT_NEAR(RestingDamperLag(p, load, m), 10 * expected, 10 * kRelativeTolerance * expected);
  // elastic, or no load: no damper
  p.law = *ParseLawName("hertz");
  ResolveLawParams(&p);
  EXPECT_TRUE(std::isinf(RestingDamperLag(p, load, m)));
  p.law = *ParseLawName("hunt-crossley");
  ResolveLawParams(&p);
  EXPECT_TRUE(std::isinf(RestingDamperLag(p, 0, m)));
}

}  // namespace
}  // namespace contactlaws
