// Copyright contactlaws authors.

#include "geometry/box_box.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/patch.h"

namespace contactlaws {
namespace {

using geometry::Add;
using geometry::Cross;
using geometry::Dot;
using geometry::NearlyParallelFaces;
using geometry::Scale;
using geometry::Sub;
using geometry::kAxisTieFraction;
using geometry::kParallelSine;

// Axis i of the box (column i of its rotation), world frame.
Vector3 Axis(const OrientedBox& box, int i) {
  return {box.rotation[i], box.rotation[3 + i], box.rotation[6 + i]};
}

// Half the box's extent along unit direction n.
double Radius(const OrientedBox& box, const Vector3& n) {
  double r = 0;
  for (int i = 0; i < 3; ++i) r += box.half[i] * std::fabs(Dot(Axis(box, i), n));
  return r;
}

// One of the 15 axes: its direction from a towards b, and how far the boxes
// are apart along it (< 0: their projections overlap by that much).
struct Candidate {
  Vector3 normal{};
  double separation = -std::numeric_limits<double>::infinity();
  BoxFeature feature = BoxFeature::kNone;
  int i = -1;  // the axis of a that made it
  int j = -1;  // the axis of b
};

Candidate Project(const OrientedBox& a, const OrientedBox& b, const Vector3& axis,
                  BoxFeature feature, int i, int j) {
  const double along = Dot(Sub(b.centre, a.centre), axis);
  Candidate c;
  c.normal = along < 0 ? Scale(axis, -1) : axis;
  c.separation = std::fabs(along) - Radius(a, axis) - Radius(b, axis);
  c.feature = feature;
  c.i = i;
  c.j = j;
  return c;
}

double LargestHalf(const OrientedBox& a, const OrientedBox& b) {
  return std::max({a.half[0], a.half[1], a.half[2], b.half[0], b.half[1], b.half[2]});
}

// The axis of least overlap (or largest separation): a face of a, else a
// face of b, else an edge pair, each only when clearly better than the one
// before (kAxisTieFraction).
Candidate SeparatingAxis(const OrientedBox& a, const OrientedBox& b) {
  const double tie = kAxisTieFraction * LargestHalf(a, b);
  Candidate face_a, face_b, edge;
  for (int k = 0; k < 3; ++k) {
    const Candidate ca = Project(a, b, Axis(a, k), BoxFeature::kFaceOfA, k, -1);
    if (ca.separation > face_a.separation) face_a = ca;
    const Candidate cb = Project(a, b, Axis(b, k), BoxFeature::kFaceOfB, -1, k);
    if (cb.separation > face_b.separation) face_b = cb;
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vector3 axis = Cross(Axis(a, i), Axis(b, j));
      const double sine = std::sqrt(Dot(axis, axis));
      if (sine < kParallelSine) continue;
      const Candidate c = Project(a, b, Scale(axis, 1 / sine), BoxFeature::kEdgeEdge, i, j);
      if (c.separation > edge.separation) edge = c;
    }
  }
  const Candidate& face = face_b.separation > face_a.separation + tie ? face_b : face_a;
  // the other box's face most nearly parallel to the reference face
  const OrientedBox& other = face.feature == BoxFeature::kFaceOfA ? b : a;
  double aligned = 0;
  for (int k = 0; k < 3; ++k) aligned = std::max(aligned, std::fabs(Dot(face.normal, Axis(other, k))));
  if (NearlyParallelFaces(aligned) || geometry::EdgeAlongFace(edge.normal, face.normal)) {
    return face;
  }
  return edge.separation > face.separation + tie ? edge : face;
}

// The face contact: ref's face with outward normal n (towards inc) against
// the face of inc most opposed to it.
void FaceContact(const OrientedBox& ref, int k, const Vector3& n, const OrientedBox& inc,
                 double margin, double merge, BoxBoxContact* out) {
  // the reference face: centre f, in-plane axes u, v with half sizes hu, hv
  const Vector3 f = Add(ref.centre, Scale(n, ref.half[k]));
  const Vector3 u = Axis(ref, (k + 1) % 3);
  const Vector3 v = Axis(ref, (k + 2) % 3);
  const double hu = ref.half[(k + 1) % 3];
  const double hv = ref.half[(k + 2) % 3];

  // the incident face: the face of inc whose outward normal is most against n
  int j = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::fabs(Dot(Axis(inc, i), n)) > std::fabs(Dot(Axis(inc, j), n))) j = i;
  }
  const double side = Dot(Axis(inc, j), n) > 0 ? -1.0 : 1.0;
  const Vector3 g = Add(inc.centre, Scale(Axis(inc, j), side * inc.half[j]));
  const Vector3 p = Scale(Axis(inc, (j + 1) % 3), inc.half[(j + 1) % 3]);
  const Vector3 q = Scale(Axis(inc, (j + 2) % 3), inc.half[(j + 2) % 3]);
  const Vector3 corners[4] = {Add(g, Add(p, q)), Add(g, Sub(q, p)), Sub(g, Add(p, q)),
                              Add(g, Sub(p, q))};

  // its corners in the reference face's frame, clipped to the face's sides
  std::array<geometry::ClipVertex, geometry::kClipCapacity> poly, next;
  for (int c = 0; c < 4; ++c) {
    const Vector3 r = Sub(corners[c], f);
    poly[c] = {{Dot(r, u), Dot(r, v), Dot(r, n)}};
  }
  const Vector3 m = Scale(Axis(inc, j), side);
  const Vector3 incident_normal = {Dot(m, u), Dot(m, v), Dot(m, n)};
  int count = 4;
  const double bounds[2] = {hu, hv};
  for (int c = 0; c < 2; ++c) {
    for (const double sign : {1.0, -1.0}) {
      count = geometry::Clip(poly.data(), count, c == 0 ? sign : 0.0, c == 1 ? sign : 0.0,
                             bounds[c], 2 * c + (sign > 0 ? 0 : 1), incident_normal, next.data());
      std::swap(poly, next);
    }
  }

  // the vertices below the reference plane (height -depth), midway points
  const geometry::Patch patch =
      geometry::PatchBelow(poly.data(), count, margin, merge, kMaxBoxBoxPoints);
  // the contact's normal is n (a's face) or -n (b's)
  const double towards_b = Dot(n, out->normal) > 0 ? 1.0 : -1.0;
  for (int c = 0; c < patch.count; ++c) {
    const Vector3& x = patch.p[c];
    const Vector3& g = patch.gradient[c];
    BoxPoint& point = out->points[c];
    point.pos = Add(Add(f, Add(Scale(u, x[0]), Scale(v, x[1]))), Scale(n, 0.5 * x[2]));
    point.depth = -x[2];
    point.weight = patch.weight[c];
    const Vector3 world = Add(Add(Scale(u, g[0]), Scale(v, g[1])), Scale(n, g[2]));
    point.gradient = Scale(world, towards_b);
  }
  out->count = patch.count;
}

// The edge-edge contact along normal (a towards b): the middle of the closest
// points of a's edge along axis i and b's edge along axis j.
void EdgeContact(const OrientedBox& a, int i, const OrientedBox& b, int j, const Vector3& normal,
                 double margin, BoxBoxContact* out) {
  // each box's edge nearest the other: a's extreme along +normal, b's along -normal
  Vector3 ea = a.centre;
  Vector3 eb = b.centre;
  for (int k = 0; k < 3; ++k) {
    if (k != i) ea = Add(ea, Scale(Axis(a, k), Dot(Axis(a, k), normal) >= 0 ? a.half[k] : -a.half[k]));
    if (k != j) eb = Add(eb, Scale(Axis(b, k), Dot(Axis(b, k), normal) > 0 ? -b.half[k] : b.half[k]));
  }
  // closest points of the two edges (their directions >= kParallelSine apart)
  Vector3 pa, pb;
  geometry::ClosestOnEdges(ea, Axis(a, i), a.half[i], eb, Axis(b, j), b.half[j], &pa, &pb);
  const double depth = Dot(Sub(pa, pb), normal);
  if (!(depth > -margin)) return;
  out->points[0] = {Scale(Add(pa, pb), 0.5), depth, 1.0, normal};
  out->count = 1;
}

}  // namespace

BoxBoxContact CollideBoxes(const OrientedBox& a, const OrientedBox& b, double margin) {
  BoxBoxContact out;
  const Candidate axis = SeparatingAxis(a, b);
  if (!(axis.separation < margin)) return out;
  out.feature = axis.feature;
  out.normal = axis.normal;
  const double merge = kBoxPointMergeFraction * std::min({a.half[0], a.half[1], a.half[2],
                                                          b.half[0], b.half[1], b.half[2]});
  switch (axis.feature) {
    case BoxFeature::kFaceOfA:
      FaceContact(a, axis.i, axis.normal, b, margin, merge, &out);
      break;
    case BoxFeature::kFaceOfB:
      FaceContact(b, axis.j, Scale(axis.normal, -1), a, margin, merge, &out);
      break;
    case BoxFeature::kEdgeEdge:
      EdgeContact(a, axis.i, b, axis.j, axis.normal, margin, &out);
      break;
    case BoxFeature::kNone:
      break;
  }
  if (out.count == 0) out.feature = BoxFeature::kNone;
  return out;
}

}  // namespace contactlaws
