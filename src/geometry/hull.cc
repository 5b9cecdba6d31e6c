// Copyright contactlaws authors.

#include "geometry/hull.h"

#include <algorithm>
#include <cmath>

namespace contactlaws {
namespace geometry {
namespace {

// The face whose normal is n (within kCoplanarSine), added if new; -1 when
// the faces are full.
int FaceOf(const Vector3& n, Hull* hull) {
  for (int f = 0; f < hull->face_count; ++f) {
    const Vector3& m = hull->faces[f].normal;
    if (Dot(n, m) > 0 && Norm(Cross(n, m)) < kCoplanarSine) return f;
  }
  if (hull->face_count == kMaxPolytopeTriangles) return -1;
  hull->faces[hull->face_count].normal = n;
  return hull->face_count++;
}

// The outward unit normal of triangle t, or false if it has no area.
bool TriangleNormal(const Polytope& p, const Vector3& centre, int t, Vector3* n) {
  const auto& tri = p.triangles[t];
  const Vector3& a = p.vertices[tri[0]];
  const Vector3 c = Cross(Sub(p.vertices[tri[1]], a), Sub(p.vertices[tri[2]], a));
  const double length = Norm(c);
  if (!(length > 0)) return false;
  *n = Scale(c, (Dot(c, Sub(a, centre)) < 0 ? -1 : 1) / length);
  return true;
}

// Records edge (i, j) of a triangle on face f: a new edge, or the second
// face of one met before.
void AddEdge(int i, int j, int f, Hull* hull) {
  const int v0 = std::min(i, j), v1 = std::max(i, j);
  for (int e = 0; e < hull->edge_count; ++e) {
    HullEdge& edge = hull->edges[e];
    if (edge.v0 == v0 && edge.v1 == v1) {
      edge.f1 = f;
      return;
    }
  }
  if (hull->edge_count == kMaxHullEdges) return;
  hull->edges[hull->edge_count++] = {v0, v1, f, -1, -1};
}

// Drops the edges inside a face (both sides on it), gives the rest their
// direction's index.
void KeepHullEdges(const Polytope& p, Hull* hull) {
  int kept = 0;
  for (int e = 0; e < hull->edge_count; ++e) {
    HullEdge edge = hull->edges[e];
    if (edge.f0 == edge.f1 || edge.f1 < 0) continue;
    const Vector3 d = Sub(p.vertices[edge.v1], p.vertices[edge.v0]);
    const Vector3 u = Scale(d, 1 / Norm(d));
    int k = 0;
    while (k < hull->direction_count && Norm(Cross(u, hull->directions[k])) >= kCoplanarSine) ++k;
    if (k == hull->direction_count) hull->directions[hull->direction_count++] = u;
    edge.direction = k;
    hull->edges[kept++] = edge;
  }
  hull->edge_count = kept;
}

}  // namespace

void Extent(const Hull& hull, const Vector3& n, double* low, double* high) {
  const Polytope& p = *hull.polytope;
  *low = *high = Dot(n, p.vertices[0]);
  for (int i = 1; i < p.vertex_count; ++i) {
    const double x = Dot(n, p.vertices[i]);
    *low = std::min(*low, x);
    *high = std::max(*high, x);
  }
}

bool BuildHull(const Polytope& p, Hull* hull) {
  hull->polytope = &p;
  hull->centre = {};
  for (int i = 0; i < p.vertex_count; ++i) {
    hull->centre = Add(hull->centre, Scale(p.vertices[i], 1.0 / p.vertex_count));
  }
  hull->face_count = hull->edge_count = hull->direction_count = 0;
  for (int t = 0; t < p.triangle_count; ++t) {
    Vector3 n;
    if (!TriangleNormal(p, hull->centre, t, &n)) return false;
    const int f = FaceOf(n, hull);
    if (f < 0) return false;
    const auto& tri = p.triangles[t];
    for (int k = 0; k < 3; ++k) AddEdge(tri[k], tri[(k + 1) % 3], f, hull);
  }
  if (hull->face_count < 4) return false;
  KeepHullEdges(p, hull);
  hull->min_half = HUGE_VAL;
  hull->max_half = 0;
  for (int f = 0; f < hull->face_count; ++f) {
    double low, high;
    Extent(*hull, hull->faces[f].normal, &low, &high);
    hull->faces[f].offset = high;
    hull->min_half = std::min(hull->min_half, 0.5 * (high - low));
    hull->max_half = std::max(hull->max_half, 0.5 * (high - low));
  }
  return true;
}

}  // namespace geometry
}  // namespace contactlaws
