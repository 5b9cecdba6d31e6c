// Copyright contactlaws authors.
//
// ExactRebound against the closed form it solves.

#include "contactlaws/hysteresis.h"

#include <cmath>

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
  // small a: e_post = 1 - 2a/3 + O(a^2) (expand the closed form), on both
  // sides of the switch from bisection to the series
  EXPECT_NEAR(ExactRebound(0.99e-4), 1 - 0.99e-4 * 2 / 3, 1e-8);
  EXPECT_NEAR(ExactRebound(1.01e-4), 1 - 1.01e-4 * 2 / 3, 1e-8);
  EXPECT_NEAR(ExactRebound(1e-16), 1.0, 1e-15);
}

}  // namespace
}  // namespace contactlaws
