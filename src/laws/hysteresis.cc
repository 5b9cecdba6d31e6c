// Copyright contactlaws authors.

#include "contactlaws/hysteresis.h"

#include <algorithm>

namespace contactlaws {

double ExactRebound(double a) {
  if (a <= 0.0) return 1.0;
  // small a: the terms of g below cancel to O(a^2); expanding e = 1 - delta
  // gives delta = 2a/3 - 4a^2/9 + O(a^3)
  if (a < 1e-4) return 1.0 - 2.0 * a / 3.0 + 4.0 * a * a / 9.0;
  // g(e) = a (1 + e) - ln((1 + a) / (1 - a e)) is concave in e, with g(0) > 0
  // (a > ln(1 + a)) and g -> -inf as e -> 1/a: bisect on (0, min(1, 1/a)).
  auto g = [a](double e) { return a * (1.0 + e) - std::log1p(a) + std::log1p(-a * e); };
  double lo = 0.0;
  double hi = std::min(1.0, 1.0 / a);
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace contactlaws
