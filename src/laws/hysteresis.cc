// Copyright contactlaws authors.

#include "contactlaws/law.h"

#include <algorithm>
#include <cmath>

namespace contactlaws {
namespace {

// Below this a, F(a, e) / a^2 is summed as a series: its closed form loses
// about log10(1/a) digits to the cancellation of its O(a) terms, its series'
// terms fall by a factor a each (30 terms: 0.05^28 < 1e-36).
constexpr double kSeriesBelow = 0.05;
constexpr int kSeriesTerms = 30;

// h(a, e) = F(a, e) / a^2, F = a (1 + e) - ln((1 + a) / (1 - a e)):
// h = sum_{k >= 2} ((-1)^k - e^k) a^(k-2) / k. For even k, 1 - e^k is
// written (1 - e)(1 + e + ... + e^(k-1)) so that it is not a difference.
// h(0+, e) = (1 - e^2) / 2, and h -> -inf as a -> 1/e, with one sign change.
double ReboundResidual(double a, double e) {
  if (a >= kSeriesBelow) {
    return (a * (1.0 + e) - std::log1p(a) + std::log1p(-a * e)) / (a * a);
  }
  const double p = 1.0 - e;
  double sum = 0.0;
  double a_power = 1.0;         // a^(k-2)
  double e_power = e * e;       // e^k
  double geometric = 1.0 + e;   // 1 + e + ... + e^(k-1)
  for (int k = 2; k < 2 + kSeriesTerms; ++k) {
    const double coefficient = k % 2 == 0 ? p * geometric : -(1.0 + e_power);
    sum += coefficient * a_power / k;
    a_power *= a;
    geometric += e_power;
    e_power *= e;
  }
  return sum;
}

// Bisection of a decreasing-through-zero f on (lo, hi) to the last bit: f(lo)
// > 0 > f(hi), never evaluated at the ends. 2000 halvings cover any pair of
// doubles.
template <typename F>
double Bisect(double lo, double hi, F f) {
  for (int i = 0; i < 2000; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (!(lo < mid && mid < hi)) break;
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double ExactRebound(double a) {
  if (a <= 0.0) return 1.0;
  // h(a, e) > 0 below the root in e and < 0 above it, up to min(1, 1/a)
  return Bisect(0.0, std::min(1.0, 1.0 / a), [a](double e) { return ReboundResidual(a, e); });
}

double ExactCoefficient(double e) {
  if (e >= 1.0) return 0.0;
  if (!(e > 0.0)) return HUGE_VAL;  // a ~ 1/e: e = 0 has none
  // F rises from 0 (it is convex up to a = (1 - e)/(2e)) and then falls to
  // -inf at 1/e: the root lies between
  return Bisect((1.0 - e) / (2.0 * e), 1.0 / e, [e](double a) { return ReboundResidual(a, e); });
}

}  // namespace contactlaws
