// Copyright contactlaws authors.

#include "geometry/patch.h"

#include <algorithm>

namespace contactlaws {
namespace geometry {
namespace {

// Distance of x from the segment a-b.
double ChordDistance(const Vector3& a, const Vector3& x, const Vector3& b) {
  const Vector3 ab = Sub(b, a);
  const double length2 = Dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(Dot(Sub(x, a), ab) / length2, 0.0, 1.0) : 0.0;
  return Norm(Sub(x, geometry::Add(a, Scale(ab, t))));
}

}  // namespace

int Clip(const Vector3* in, int n, double a, double b, double h, Vector3* out) {
  int m = 0;
  for (int k = 0; k < n && m < kClipCapacity - 1; ++k) {
    const Vector3& p = in[k];
    const Vector3& q = in[(k + 1) % n];
    const double dp = a * p[0] + b * p[1] - h;
    const double dq = a * q[0] + b * q[1] - h;
    if (dp <= 0) out[m++] = p;
    if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {
      out[m++] = geometry::Add(p, Scale(Sub(q, p), dp / (dp - dq)));
    }
  }
  return m;
}

void Patch::Add(const Vector3& x, double merge) {
  for (int k = 0; k < count; ++k) {
    const Vector3 d = Sub(x, p[k]);
    if (Dot(d, d) < merge * merge) {
      const double w = 1.0 / ++merged[k];
      p[k] = geometry::Add(Scale(p[k], 1 - w), Scale(x, w));
      return;
    }
  }
  if (count == kClipCapacity) return;
  p[count] = x;
  merged[count++] = 1;
}

void Patch::Order() {
  double cu = 0, cv = 0;
  for (int k = 0; k < count; ++k) {
    cu += p[k][0] / count;
    cv += p[k][1] / count;
  }
  std::sort(p.begin(), p.begin() + count, [&](const Vector3& x, const Vector3& y) {
    return std::atan2(x[1] - cv, x[0] - cu) < std::atan2(y[1] - cv, y[0] - cu);
  });
}

void Patch::Simplify(double merge, int max_points) {
  while (count > 3) {
    int drop = -1;
    double nearest = count > max_points ? HUGE_VAL : merge;
    for (int k = 0; k < count; ++k) {
      const double d = ChordDistance(p[(k + count - 1) % count], p[k], p[(k + 1) % count]);
      if (d < nearest) {
        nearest = d;
        drop = k;
      }
    }
    if (drop < 0) return;
    std::copy(p.begin() + drop + 1, p.begin() + count, p.begin() + drop);
    --count;
  }
}

Patch PatchBelow(const Vector3* clipped, int count, double margin, double merge, int max_points) {
  Patch patch;
  for (int c = 0; c < count; ++c) {
    if (-clipped[c][2] > -margin) patch.Add(clipped[c], merge);
  }
  patch.Order();
  patch.Simplify(merge, max_points);
  return patch;
}

void ClosestOnEdges(const Vector3& ca, const Vector3& da, double half_a, const Vector3& cb,
                    const Vector3& db, double half_b, Vector3* pa, Vector3* pb) {
  const Vector3 w = Sub(ca, cb);
  const double c = Dot(da, db);
  const double wa = Dot(da, w);
  const double wb = Dot(db, w);
  const double denominator = 1 - c * c;
  const double s = std::clamp((c * wb - wa) / denominator, -half_a, half_a);
  const double t = std::clamp((wb - c * wa) / denominator, -half_b, half_b);
  *pa = geometry::Add(ca, Scale(da, s));
  *pb = geometry::Add(cb, Scale(db, t));
}

}  // namespace geometry
}  // namespace contactlaws
