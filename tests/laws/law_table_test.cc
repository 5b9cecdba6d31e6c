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
    EXPECT_EQ(static_cast<size_t>(law.kind), i) << law.name;
    EXPECT_TRUE(names.insert(law.name).second) << law.name << " twice";
    for (const char c : law.name) {
      EXPECT_TRUE((c >= 'a' && c <= 'z') || c == '-') << law.name;
    }
    EXPECT_FALSE(law.formula.empty()) << law.name;
    EXPECT_FALSE(law.parameters.empty()) << law.name;
    EXPECT_FALSE(law.reference.empty()) << law.name;
    EXPECT_EQ(ParseLawName(law.name), law.kind);
    EXPECT_NE(LawNameList().find(law.name), std::string::npos) << law.name;
    EXPECT_EQ(law.family == LawFamily::kLinear, law.kind == LawKind::kKelvinVoigt) << law.name;
  }
  EXPECT_EQ(AllLaws().size(), Laws().size());
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
    EXPECT_EQ(HysteresisCoefficient(law.kind, 1.0), 0.0) << law.name;
    for (double e = law.restitution_excludes_zero ? kSmallest : 0.0; e <= 1.0; e += kGrid) {
      const double a = HysteresisCoefficient(law.kind, e);
      ASSERT_TRUE(std::isfinite(a) && a >= 0) << law.name << " e = " << e << ": a = " << a;
      const std::optional<double> rebound = EffectiveRestitution(law.kind, e);
      ASSERT_TRUE(rebound && *rebound > 0 && *rebound <= 1) << law.name << " e = " << e;
    }
    if (law.restitution_excludes_zero) {
      EXPECT_GT(HysteresisCoefficient(law.kind, kSmallest), kUnbounded) << law.name;
      EXPECT_FALSE(EffectiveRestitution(law.kind, 0.0).has_value()) << law.name;
    }
  }
}

TEST(LawTableTest, HertzIsElasticAndKelvinVoigtHasNoClosedForm) {
  EXPECT_EQ(HysteresisCoefficient(LawKind::kHertz, 0.3), 0.0);
  EXPECT_EQ(EffectiveRestitution(LawKind::kHertz, 0.3), 1.0);
  EXPECT_EQ(ReportedRestitution(LawKind::kHertz, 0.3), 1.0);
  EXPECT_EQ(ReportedRestitution(LawKind::kFlores, 0.3), 0.3);
  EXPECT_FALSE(EffectiveRestitution(LawKind::kKelvinVoigt, 0.3).has_value());
}

// One test per law: its a(e) by hand at a point of its range.

TEST(LawTableTest, HuntCrossleyByHand) {
  // e = 0.6: a = 3 * 0.4 / 2 = 0.6
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(LawKind::kHuntCrossley, 0.6), 0.6);
}

TEST(LawTableTest, LankaraniNikraveshByHand) {
  // e = 0.6: a = 3 * (1 - 0.36) / 4 = 0.48
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(LawKind::kLankaraniNikravesh, 0.6), 0.48);
}

TEST(LawTableTest, FloresByHand) {
  // e = 0.5: a = 8 * 0.5 / 2.5 = 1.6
  EXPECT_DOUBLE_EQ(HysteresisCoefficient(LawKind::kFlores, 0.5), 1.6);
}

}  // namespace
}  // namespace contactlaws
