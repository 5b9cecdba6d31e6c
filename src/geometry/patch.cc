// Copyright contactlaws authors.

#include "geometry/patch.h"

#include <algorithm>

namespace contactlaws {
namespace geometry {

int Clip(const ClipVertex* in, int n, double a, double b, double h, int side,
         const Vector3& incident_normal, ClipVertex* out) {
  const uint64_t bit = uint64_t{1} << side;
  int m = 0;
  for (int k = 0; k < n && m < kClipCapacity - 1; ++k) {
    const ClipVertex& p = in[k];
    const ClipVertex& q = in[(k + 1) % n];
    const double dp = a * p.p[0] + b * p.p[1] - h;
    const double dq = a * q.p[0] + b * q.p[1] - h;
    if (dp <= 0) out[m++] = p;
    if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {
      ClipVertex& x = out[m++];
      x.p = geometry::Add(p.p, Scale(Sub(q.p, p.p), dp / (dp - dq)));
      const uint64_t along = p.sides & q.sides;
      x.sides = along | bit;
      if (along != 0) {
        // p q runs along an earlier side: x is the reference face's corner
        x.gradient = Scale(incident_normal, 1 / incident_normal[2]);
      } else {
        // p q is part of an incident edge: s . e = dp - dq, nonzero here
        const double rise = (q.p[2] - p.p[2]) / (dq - dp);
        x.gradient = {-a * rise, -b * rise, 1};
      }
    }
  }
  return m;
}

namespace {

// Keeps the part of polygon in (n vertices) at height <= level; writes it to
// out, returns its count.
int ClipHeight(const ClipVertex* in, int n, double level, ClipVertex* out) {
  int m = 0;
  for (int k = 0; k < n && m < kClipCapacity - 1; ++k) {
    const ClipVertex& p = in[k];
    const ClipVertex& q = in[(k + 1) % n];
    const double dp = p.p[2] - level;
    const double dq = q.p[2] - level;
    if (dp <= 0) out[m++] = p;
    if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {
      // on the plane by construction: at zero depth, not round-off below
      // (where no force acts: the normal's gradient)
      ClipVertex& x = out[m++];
      x.p = geometry::Add(p.p, Scale(Sub(q.p, p.p), dp / (dp - dq)));
      x.p[2] = level;
      x.gradient = {0, 0, 1};
      x.sides = 0;
    }
  }
  return m;
}

// Merges each vertex closer than merge to the last one kept (around the
// polygon, the last against the first too) into it, the deeper of the two
// kept with the gradient nearer the normal of the two (a corner split by
// round-off across a side plane: the split on an edge nearly along the side
// has a large sideways gradient that the corner does not); returns the count
// left.
int MergeClose(ClipVertex* p, int n, double merge) {
  const auto close = [&](const ClipVertex& x, const ClipVertex& y) {
    const Vector3 d = Sub(x.p, y.p);
    return Dot(d, d) < merge * merge;
  };
  const auto into = [](const ClipVertex& x, ClipVertex* kept) {
    const Vector3 gradient =
        Dot(x.gradient, x.gradient) < Dot(kept->gradient, kept->gradient) ? x.gradient
                                                                          : kept->gradient;
    if (x.p[2] < kept->p[2]) kept->p = x.p;
    kept->gradient = gradient;
    kept->sides |= x.sides;
  };
  int m = 0;
  for (int k = 0; k < n; ++k) {
    if (m > 0 && close(p[k], p[m - 1])) {
      into(p[k], &p[m - 1]);
      continue;
    }
    p[m++] = p[k];
  }
  while (m > 1 && close(p[m - 1], p[0])) {
    into(p[m - 1], &p[0]);
    --m;
  }
  return m;
}

// Each vertex's weight: kPatchWeight times its exterior angle (the turn
// between its two edges, in the plane: u, v) over a full turn; equal shares
// on a polygon of no extent.
void AngleWeights(const ClipVertex* p, int n, double* weight) {
  double total = 0;
  for (int k = 0; k < n; ++k) {
    const Vector3& a = p[(k + n - 1) % n].p;
    const Vector3& b = p[k].p;
    const Vector3& c = p[(k + 1) % n].p;
    const double eu = b[0] - a[0], ev = b[1] - a[1];
    const double fu = c[0] - b[0], fv = c[1] - b[1];
    // zero for a vertex on a straight edge or one of a zero-length edge
    weight[k] = std::abs(std::atan2(eu * fv - ev * fu, eu * fu + ev * fv));
    total += weight[k];
  }
  for (int k = 0; k < n; ++k) {
    weight[k] = total > 0 ? kPatchWeight * weight[k] / total : kPatchWeight / n;
  }
}

// Orders patch points [from, to) by angle about their centre, from the u axis.
void Order(Patch* patch, int from, int to) {
  if (to - from < 2) return;
  double cu = 0, cv = 0;
  for (int k = from; k < to; ++k) {
    cu += patch->p[k][0] / (to - from);
    cv += patch->p[k][1] / (to - from);
  }
  std::array<int, kClipCapacity> order;
  for (int k = from; k < to; ++k) order[k] = k;
  const auto angle = [&](int k) { return std::atan2(patch->p[k][1] - cv, patch->p[k][0] - cu); };
  std::sort(order.begin() + from, order.begin() + to,
            [&](int x, int y) { return angle(x) < angle(y); });
  const Patch copy = *patch;
  for (int k = from; k < to; ++k) {
    patch->p[k] = copy.p[order[k]];
    patch->weight[k] = copy.weight[order[k]];
    patch->gradient[k] = copy.gradient[order[k]];
  }
}

// Removes point k of patch, the rest moving up.
void Remove(Patch* patch, int k) {
  std::copy(patch->p.begin() + k + 1, patch->p.begin() + patch->count, patch->p.begin() + k);
  std::copy(patch->weight.begin() + k + 1, patch->weight.begin() + patch->count,
            patch->weight.begin() + k);
  std::copy(patch->gradient.begin() + k + 1, patch->gradient.begin() + patch->count,
            patch->gradient.begin() + k);
  --patch->count;
}

// While more than max_points: the lightest point's weight goes to the point
// nearest it, and it goes.
void Reduce(Patch* patch, int max_points) {
  while (patch->count > max_points && patch->count > 1) {
    int lightest = 0;
    for (int k = 1; k < patch->count; ++k) {
      if (patch->weight[k] < patch->weight[lightest]) lightest = k;
    }
    int nearest = -1;
    double best = HUGE_VAL;
    for (int k = 0; k < patch->count; ++k) {
      const Vector3 d = Sub(patch->p[k], patch->p[lightest]);
      if (k != lightest && Dot(d, d) < best) {
        best = Dot(d, d);
        nearest = k;
      }
    }
    patch->weight[nearest] += patch->weight[lightest];
    Remove(patch, lightest);
  }
}

}  // namespace

Patch PatchBelow(const ClipVertex* clipped, int count, double margin, double merge,
                 int max_points) {
  Patch patch;
  std::array<ClipVertex, kClipCapacity> poly;
  std::array<double, kClipCapacity> weight;
  // in contact: the polygon below the plane
  int n = MergeClose(poly.data(), ClipHeight(clipped, count, 0.0, poly.data()), merge);
  AngleWeights(poly.data(), n, weight.data());
  for (int k = 0; k < n; ++k) {
    if (!(poly[k].p[2] < 0)) continue;
    patch.p[patch.count] = poly[k].p;
    patch.gradient[patch.count] = poly[k].gradient;
    patch.weight[patch.count++] = weight[k];
  }
  Reduce(&patch, max_points);
  Order(&patch, 0, patch.count);
  if (!(margin > 0)) return patch;

  // within the margin: the vertices of the polygon below height margin that
  // are not below the plane, the nearest first
  const int deep = patch.count;
  n = MergeClose(poly.data(), ClipHeight(clipped, count, margin, poly.data()), merge);
  AngleWeights(poly.data(), n, weight.data());
  std::array<int, kClipCapacity> near;
  int near_count = 0;
  for (int k = 0; k < n; ++k) {
    if (poly[k].p[2] >= 0 && poly[k].p[2] < margin) near[near_count++] = k;
  }
  std::sort(near.begin(), near.begin() + near_count,
            [&](int x, int y) { return poly[x].p[2] < poly[y].p[2]; });
  for (int k = 0; k < near_count && patch.count < max_points; ++k) {
    patch.p[patch.count] = poly[near[k]].p;
    patch.gradient[patch.count] = poly[near[k]].gradient;
    patch.weight[patch.count++] = weight[near[k]];
  }
  Order(&patch, deep, patch.count);
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
