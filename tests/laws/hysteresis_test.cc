// Copyright contactlaws authors.
//
// ExactRebound against the closed form it solves, and ExactCoefficient (the
// a(e) of the law `exact`) against ExactRebound.

#include "contactlaws/law.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

namespace contactlaws {
namespace {

TEST(HysteresisTest, ExactReboundSolvesTheClosedForm) {
  EXPECT_EQ(ExactRebound(0.0), 1.0);
  for (double a : {0.01, 0.15, 0.5, 1.0, 1.6, 5.0, 14.4}) {
    const double e = ExactRebound(a);
    EXPECT_GT(e, 0.0);
    EXPECT_LT(e, 1.0);
    // e is the root to 1e-10: the two sides cross between e -/+ 1e-10 (a
    // residual test would not do: at a = 14.4, 1 - a e ~ 1e-7 and the log's
    // slope a / (1 - a e) ~ 1e8 amplifies rounding)
    auto g = [a](double x) { return a * (1 + x) - std::log1p(a) + std::log1p(-a * x); };
    EXPECT_GT(g(e - 1e-10), 0.0) << "a = " << a;
    EXPECT_LT(g(e + 1e-10), 0.0) << "a = " << a;
  }
  // small a: e_post = 1 - 2a/3 + 4a^2/9 + O(a^3) (expand the closed form),
  // on both sides of the switch from the series of F/a^2 to its closed form
  for (double a : {1e-4, 0.049, 0.051}) {
    EXPECT_NEAR(ExactRebound(a), 1 - 2 * a / 3 + 4 * a * a / 9, a * a * a) << "a = " << a;
  }
  EXPECT_NEAR(ExactRebound(1e-16), 1.0, 1e-15);
}

// The law `exact`: its a(e) rebounds at e, over (0, 1]. Both bisections end
// at the last bit of their root, and F/a^2 is summed without cancellation for
// small a: what is left is rounding (measured 4e-15 at worst); 1e-12 would
// still catch the closed form used for small a (it loses ~1e-16/a^2 in F/a^2).
TEST(HysteresisTest, ExactCoefficientReboundsAtE) {
  constexpr double kRoundTrip = 1e-12;
  EXPECT_EQ(ExactCoefficient(1.0), 0.0);
  EXPECT_TRUE(std::isinf(ExactCoefficient(0.0)));
  double worst = 0;
  auto check = [&](double e) {
    const double a = ExactCoefficient(e);
    ASSERT_TRUE(std::isfinite(a) && a > 0) << "e = " << e;
    worst = std::max(worst, std::abs(ExactRebound(a) - e));
    EXPECT_NEAR(ExactRebound(a), e, kRoundTrip) << "e = " << e << ", a = " << a;
  };
  for (int i = 1; i < 1000; ++i) check(i * 1e-3);
  for (double e : {1e-6, 1e-4, 0.999999, 1 - 1e-9, 1 - 1e-12}) check(e);
  std::printf("largest |ExactRebound(ExactCoefficient(e)) - e|: %.1e\n", worst);

  // the values of an independent bisection (docs/laws.md, 7 digits), the
  // series 3p/2 + 3p^2/2 + 27p^3/20 near e = 1, and a -> 1/e near 0
  EXPECT_NEAR(ExactCoefficient(0.9), 0.166482, 1e-6);
  EXPECT_NEAR(ExactCoefficient(0.5), 1.432751, 1e-6);
  EXPECT_NEAR(ExactCoefficient(0.1), 9.998159, 1e-6);
  const double p = 1e-3;
  EXPECT_NEAR(ExactCoefficient(1 - p), 1.5 * p + 1.5 * p * p + 1.35 * p * p * p, 2 * p * p * p * p);
  EXPECT_NEAR(ExactCoefficient(0.05) * 0.05, 1.0, 1e-7);
}

}  // namespace
}  // namespace contactlaws
