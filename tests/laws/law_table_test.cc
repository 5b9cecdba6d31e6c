// Copyright contactlaws authors.
//
// The table of laws: every row complete and consistent, and each law's a(e)
// by hand. No MuJoCo here.

#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "contactlaws/law.h"

namespace contactlaws {
namespace {

// Every row: its kind is its index, its name is unique and as written in
// tags, its texts are there.
TEST(LawTableTest, RowsAreComplete) {
  std::set<std::string_view> names;
  for (size_t i = 0; i < Laws().size(); ++i) {
    const LawInfo& law = Laws()[i];
    EXPECT_EQ(static_cast<size_t>(law.id), i) << law.name;
    EXPECT_TRUE(names.insert(law.name).second) << law.name << " twice";
    for (const char c : law.name) {
      EXPECT_TRUE((c >= 'a' && c <= 'z') || c == '-') << law.name;
    }
    EXPECT_FALSE(law.formula.empty()) << law.name;
    EXPECT_FALSE(law.parameters.empty()) << law.name;
    EXPECT_FALSE(law.reference.empty()) << law.name;
    EXPECT_EQ(ParseLawName(law.name), law.id);
    EXPECT_NE(LawNameList().find(law.name), std::string::npos) << law.name;
    EXPECT_EQ(law.family == LawFamily::kLinear, law.id == *ParseLawName("kelvin-voigt")) << law.name;
  }
  EXPECT_EQ(AllLaws().size(), Laws().size());
  // the named ids are the rows the code refers to
  EXPECT_EQ(LawName(*ParseLawName("hertz")), "hertz");
  EXPECT_EQ(LawName(*ParseLawName("kelvin-voigt")), "kelvin-voigt");
  EXPECT_EQ(LawName(*ParseLawName("hunt-crossley")), "hunt-crossley");
  EXPECT_EQ(LawName(*ParseLawName("lankarani-nikravesh")), "lankarani-nikravesh");
  EXPECT_EQ(LawName(*ParseLawName("flores")), "flores");
  EXPECT_FALSE(ParseLawName("Flores").has_value());
  EXPECT_FALSE(ParseLawName("hooke").has_value());
}

// Every law of the hysteresis family: a(1) = 0 (e = 1 is Hertz), a(e) finite
// and >= 0 over its range of e, and a rebound in (0, 1] there; a law that
// refuses e = 0 has an a(e) that grows without bound towards it.
TEST(LawTableTest, HysteresisCoefficientsOverTheRangeOfE) {
  // e in its range on a grid of 1e-3, and the smallest e of laws that
  // refuse 0: 1e-6 (a(e) of the 1/e laws is then > 1e5)
  constexpr double kGrid = 1e-3;
  constexpr double kSmallest = 1e-6;
  constexpr double kUnbounded = 1e5;
  for (const LawInfo& law : Laws()) {
    if (law.family != LawFamily::kHysteresis || !law.hysteresis) continue;
    EXPECT_EQ(HysteresisCoefficient(law.id, 1.0), 0.0) << law.name;
    for (double e = law.restitution_excludes_zero ? kSmallest : 0.0; e <= 1.0; e += kGrid) {
      const double a = HysteresisCoefficient(law.id, e);
      ASSERT_TRUE(std::isfinite(a) && a >= 0) << law.name << " e = " << e << ": a = " << a;
      const std::optional<double> rebound = EffectiveRestitution(law.id, e);
      ASSERT_TRUE(rebound && *rebound > 0 && *rebound <= 1) << law.name << " e = " << e;
    }
    if (law.restitution_excludes_zero) {
      EXPECT_GT(HysteresisCoefficient(law.id, kSmallest), kUnbounded) << law.name;
      EXPECT_FALSE(EffectiveRestitution(law.id, 0.0).has_value()) << law.name;
    }
  }
}

// A law refuses e = 0 (naming itself) exactly when its a(e) grows without
// bound as e -> 0 (> 1e5 at e = 1e-6, where the 1/e laws give >= 1e6 and the
// others at most 5.54); the others take e = 0.
TEST(LawTableTest, RangesOfE) {
  constexpr double kTiny = 1e-6;
  constexpr double kUnbounded = 1e5;
  for (const LawInfo& law : Laws()) {
    const bool unbounded = HysteresisCoefficient(law.id, kTiny) > kUnbounded;
    EXPECT_EQ(law.restitution_excludes_zero, unbounded) << law.name;
    LawParams p;
    p.law = law.id;
    p.stiffness = 1e6;
    p.linear_stiffness = 1e6;
    p.dissipation = 0.1;
    p.restitution = 0.0;
    const std::optional<ParamError> error = ValidateLawParams(p);
    if (unbounded) {
      ASSERT_TRUE(error.has_value()) << law.name;
      EXPECT_EQ(error->key, "restitution");
      EXPECT_EQ(error->requirement, "must be in (0, 1] for " + std::string(law.name));
    } else {
      EXPECT_FALSE(error.has_value()) << law.name;
    }
    // above 1 every law that reads e refuses it: a < 0 would gain energy
    p.restitution = 1.0 + 1e-9;
    EXPECT_EQ(ValidateLawParams(p).has_value(), ReadsRestitution(law.id)) << law.name;
  }
}

TEST(LawTableTest, HertzIsElasticAndKelvinVoigtHasNoClosedForm) {
  EXPECT_EQ(HysteresisCoefficient(*ParseLawName("hertz"), 0.3), 0.0);
  EXPECT_EQ(EffectiveRestitution(*ParseLawName("hertz"), 0.3), 1.0);
  EXPECT_EQ(ReportedRestitution(*ParseLawName("hertz"), 0.3), 1.0);
  EXPECT_EQ(ReportedRestitution(*ParseLawName("flores"), 0.3), 0.3);
  EXPECT_EQ(ReportedRestitution(*ParseLawName("kelvin-voigt"), 0.3), 0.3);
  EXPECT_FALSE(EffectiveRestitution(*ParseLawName("kelvin-voigt"), 0.3).has_value());
}

// One test per law: its a(e) by hand at a point of its range.

TEST(LawTableTest, HuntCrossleyByHand) {
  // e = 0.6: a = 3 * 0.4 / 2 = 0.6
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(*ParseLawName("hunt-crossley"), 0.6), 0.6);
}

TEST(LawTableTest, LankaraniNikraveshByHand) {
  // e = 0.6: a = 3 * (1 - 0.36) / 4 = 0.48
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(*ParseLawName("lankarani-nikravesh"), 0.6), 0.48);
}

TEST(LawTableTest, FloresByHand) {
  // e = 0.5: a = 8 * 0.5 / 2.5 = 1.6
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(*ParseLawName("flores"), 0.5), 1.6);
}

// The laws added after the paper, found by name. Each: a(e) by hand, and the
// force K d^n (1 + a d'/v0) at d = 1e-3 m, d' = 2 m/s, v0 = 4 m/s, K = 1e8,
// n = 1.5: K d^n = 1e8 * 3.16227766e-5 = 3162.27766 N, factor 1 + a/2.

LawId Named(std::string_view name) {
  const std::optional<LawId> kind = ParseLawName(name);
  EXPECT_TRUE(kind.has_value()) << name;
  return kind.value_or(*ParseLawName("hertz"));
}

// Kernel arithmetic is a few flops (the exact law's a is a root to the last
// bit): the force agrees with the hand value to rounding.
constexpr double kRoundoff = 1e-12;
constexpr double kHertzForce = 3162.2776601683795;  // 1e8 * (1e-3)^1.5, N

double Force(std::string_view name, double e) {
  LawParams p;
  p.law = Named(name);
  p.restitution = e;
  p.stiffness = 1e8;
  p.exponent = 1.5;
  p.dissipation = 0.5;
  EXPECT_FALSE(ValidateLawParams(p).has_value()) << name;
  ResolveLawParams(&p);
  return EvaluateLaw(p, ContactState{1e-3, 2.0, 4.0, 1.0}).total;
}

TEST(LawTableTest, HerbertMcWhannellByHand) {
  // e = 0.5: a = 6 * 0.5 / (0^2 + 3) = 1; e = 0: a = 6 / 4 = 1.5
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(Named("herbert-mcwhannell"), 0.5), 1.0);
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(Named("herbert-mcwhannell"), 0.0), 1.5);
  EXPECT_NEAR(Force("herbert-mcwhannell", 0.5), 1.5 * kHertzForce, kRoundoff * kHertzForce);
}

TEST(LawTableTest, LeeWangByHand) {
  // e = 0.6: a = 3 * 0.4 / 4 = 0.3
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(Named("lee-wang"), 0.6), 0.3);
  EXPECT_NEAR(Force("lee-wang", 0.6), 1.15 * kHertzForce, kRoundoff * kHertzForce);
}

TEST(LawTableTest, GonthierByHand) {
  // e = 0.5: a = (1 - 0.25) / 0.5 = 1.5
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(Named("gonthier"), 0.5), 1.5);
  EXPECT_NEAR(Force("gonthier", 0.5), 1.75 * kHertzForce, kRoundoff * kHertzForce);
}

TEST(LawTableTest, ZhiyingQishaoByHand) {
  // e = 0.5: a = 3 * 0.75 * exp(1) / 4 = 0.5625 * 2.718281828 = 1.529033528
  EXPECT_NEAR(HysteresisCoefficient(Named("zhiying-qishao"), 0.5), 1.529033528, 1e-9);
  // e = 0: a = 0.75 e^2 = 5.541792, finite
  EXPECT_NEAR(HysteresisCoefficient(Named("zhiying-qishao"), 0.0), 5.541792, 1e-6);
  EXPECT_NEAR(Force("zhiying-qishao", 0.5), (1 + 0.5625 * std::exp(1.0) / 2) * kHertzForce,
              kRoundoff * kHertzForce);
}

TEST(LawTableTest, HuGuoByHand) {
  // e = 0.6: a = 3 * 0.4 / 1.2 = 1 (the 3(1-e)/(4e) version would give 0.5)
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(Named("hu-guo"), 0.6), 1.0);
  EXPECT_NEAR(Force("hu-guo", 0.6), 1.5 * kHertzForce, kRoundoff * kHertzForce);
}

TEST(LawTableTest, GharibHurmuzluByHand) {
  // e = 0.25: a = 0.75 / 0.25 = 3
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(Named("gharib-hurmuzlu"), 0.25), 3.0);
  EXPECT_NEAR(Force("gharib-hurmuzlu", 0.25), 2.5 * kHertzForce, kRoundoff * kHertzForce);
}

TEST(LawTableTest, ExactByHand) {
  // e = 0.5: a = 1.432751 (an independent bisection, docs/laws.md); it solves
  // a (1 + e) = ln((1 + a) / (1 - a e)): 2.149126 = ln(2.432751 / 0.283625)
  const double a = HysteresisCoefficient(Named("exact"), 0.5);
  EXPECT_NEAR(a, 1.432751, 1e-6);
  EXPECT_NEAR(1.5 * a, std::log((1 + a) / (1 - 0.5 * a)), 1e-12);
  EXPECT_NEAR(*EffectiveRestitution(Named("exact"), 0.5), 0.5, 1e-12);
  EXPECT_NEAR(Force("exact", 0.5), (1 + a / 2) * kHertzForce, kRoundoff * kHertzForce);
}

TEST(LawTableTest, HuntCrossleyConstantByHand) {
  // F = K d^n (1 + c d'): c = 0.5 s/m, d' = 2 m/s: factor 2, whatever e and v0
  EXPECT_NEAR(Force("hunt-crossley-constant", 0.3), 2.0 * kHertzForce, kRoundoff * kHertzForce);
  EXPECT_EQ(Force("hunt-crossley-constant", 0.9), Force("hunt-crossley-constant", 0.3));
  // no a(e): its rebound, ExactRebound(c v0), depends on the impact speed
  EXPECT_EQ(HysteresisCoefficient(Named("hunt-crossley-constant"), 0.5), 0.0);
  EXPECT_FALSE(EffectiveRestitution(Named("hunt-crossley-constant"), 0.5).has_value());
  EXPECT_FALSE(ReadsRestitution(Named("hunt-crossley-constant")));
  EXPECT_TRUE(ReadsDissipation(Named("hunt-crossley-constant")));
  EXPECT_FALSE(ReportedRestitution(Named("hunt-crossley-constant"), 0.5).has_value());
  // it needs its dissipation, >= 0
  LawParams p;
  p.law = Named("hunt-crossley-constant");
  p.stiffness = 1e8;
  ASSERT_TRUE(ValidateLawParams(p).has_value());
  EXPECT_EQ(ValidateLawParams(p)->key, "dissipation");
  p.dissipation = -1;
  EXPECT_EQ(ValidateLawParams(p)->key, "dissipation");
  p.dissipation = 0;
  EXPECT_FALSE(ValidateLawParams(p).has_value());
}

}  // namespace
}  // namespace contactlaws
