// Copyright contactlaws authors.

#include "geometry/polytope.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/hull.h"
#include "geometry/patch.h"

namespace contactlaws {
namespace {

using geometry::Add;
using geometry::Cross;
using geometry::Dot;
using geometry::Hull;
using geometry::NearlyParallelFaces;
using geometry::Norm;
using geometry::Scale;
using geometry::Sub;
using geometry::kAxisTieFraction;
using geometry::kParallelSine;

struct Candidate {
  Vector3 normal{};  // from a towards b
  double separation = -std::numeric_limits<double>::infinity();
  PolytopeFeature feature = PolytopeFeature::kNone;
  int i = -1;  // a's face or edge direction
  int j = -1;  // b's
};

// The axis of least overlap: a face of a, else a face of b, else an edge
// pair, each only when clearly better than the one before; the face's axis
// whatever an edge pair's says when the incident face is nearly parallel to
// it (patch.h, kParallelFaceSine).
Candidate SeparatingAxis(const Hull& a, const Hull& b) {
  const double tie = kAxisTieFraction * std::max(a.max_half, b.max_half);
  Candidate face_a, face_b, edge;
  double low, high;
  for (int f = 0; f < a.face_count; ++f) {
    Extent(b, a.faces[f].normal, &low, &high);
    const double s = low - a.faces[f].offset;
    if (s > face_a.separation) face_a = {a.faces[f].normal, s, PolytopeFeature::kFaceOfA, f, -1};
  }
  for (int f = 0; f < b.face_count; ++f) {
    Extent(a, b.faces[f].normal, &low, &high);
    const double s = low - b.faces[f].offset;
    const Vector3 n = Scale(b.faces[f].normal, -1);
    if (s > face_b.separation) face_b = {n, s, PolytopeFeature::kFaceOfB, -1, f};
  }
  for (int i = 0; i < a.direction_count; ++i) {
    for (int j = 0; j < b.direction_count; ++j) {
      const Vector3 axis = Cross(a.directions[i], b.directions[j]);
      const double sine = Norm(axis);
      if (sine < kParallelSine) continue;
      const Vector3 n = Scale(axis, 1 / sine);
      double a_low, a_high, b_low, b_high;
      Extent(a, n, &a_low, &a_high);
      Extent(b, n, &b_low, &b_high);
      const double up = b_low - a_high, down = a_low - b_high;
      const Candidate c{up >= down ? n : Scale(n, -1), std::max(up, down),
                        PolytopeFeature::kEdgeEdge, i, j};
      if (c.separation > edge.separation) edge = c;
    }
  }
  const Candidate& face = face_b.separation > face_a.separation + tie ? face_b : face_a;
  // the other polytope's face most opposed to the reference face (the
  // incident face); face.normal is a's outward normal or b's inward one
  const Hull& other = face.feature == PolytopeFeature::kFaceOfA ? b : a;
  const double sign = face.feature == PolytopeFeature::kFaceOfA ? -1 : 1;
  double opposed = -1;
  for (int g = 0; g < other.face_count; ++g) {
    opposed = std::max(opposed, sign * Dot(face.normal, other.faces[g].normal));
  }
  if (NearlyParallelFaces(opposed) || geometry::EdgeAlongFace(edge.normal, face.normal)) {
    return face;
  }
  return edge.separation > face.separation + tie ? edge : face;
}

// A face's polygon in the reference face's frame: the vertices of hull on
// face, in the frame (u, v, w) about origin f, ordered by angle about their
// centre. Returns their count, or -1 beyond kMaxFaceVertices.
int FacePolygon(const Hull& hull, const geometry::HullFace& face, const Vector3& f,
                const Vector3& u, const Vector3& v, const Vector3& w, Vector3* out) {
  const Polytope& p = *hull.polytope;
  const double tolerance = kCoplanarSine * 2 * hull.max_half;
  int count = 0;
  for (int i = 0; i < p.vertex_count; ++i) {
    if (std::fabs(Dot(face.normal, p.vertices[i]) - face.offset) > tolerance) continue;
    if (count == kMaxFaceVertices) return -1;
    const Vector3 r = Sub(p.vertices[i], f);
    out[count++] = {Dot(r, u), Dot(r, v), Dot(r, w)};
  }
  double cu = 0, cv = 0;
  for (int k = 0; k < count; ++k) {
    cu += out[k][0] / count;
    cv += out[k][1] / count;
  }
  std::sort(out, out + count, [&](const Vector3& x, const Vector3& y) {
    return std::atan2(x[1] - cv, x[0] - cu) < std::atan2(y[1] - cv, y[0] - cu);
  });
  return count;
}

// The reference face's frame: its centre f (the mean of its vertices), u
// towards its vertex of lowest index, v = n x u.
void FaceFrame(const Hull& hull, const geometry::HullFace& face, Vector3* f, Vector3* u,
               Vector3* v) {
  const Polytope& p = *hull.polytope;
  const double tolerance = kCoplanarSine * 2 * hull.max_half;
  int first = -1, count = 0;
  *f = {};
  for (int i = 0; i < p.vertex_count; ++i) {
    if (std::fabs(Dot(face.normal, p.vertices[i]) - face.offset) > tolerance) continue;
    if (first < 0) first = i;
    *f = Add(*f, p.vertices[i]);
    ++count;
  }
  *f = Scale(*f, 1.0 / count);
  const Vector3 r = Sub(p.vertices[first], *f);
  *u = Sub(r, Scale(face.normal, Dot(r, face.normal)));
  *u = Scale(*u, 1 / Norm(*u));
  *v = Cross(face.normal, *u);
}

// The face contact: ref's face k (outward normal towards inc) against inc's
// face most opposed to it. False beyond kMaxFaceVertices.
bool FaceContact(const Hull& ref, int k, const Hull& inc, double margin, double merge,
                 PolytopeContact* out) {
  const geometry::HullFace& face = ref.faces[k];
  Vector3 f, u, v;
  FaceFrame(ref, face, &f, &u, &v);
  int j = 0;
  for (int g = 1; g < inc.face_count; ++g) {
    if (Dot(inc.faces[g].normal, face.normal) < Dot(inc.faces[j].normal, face.normal)) j = g;
  }
  std::array<Vector3, geometry::kClipCapacity> side, corners;
  std::array<geometry::ClipVertex, geometry::kClipCapacity> poly, next;
  const int sides = FacePolygon(ref, face, f, u, v, face.normal, side.data());
  int count = FacePolygon(inc, inc.faces[j], f, u, v, face.normal, corners.data());
  if (sides < 0 || count < 0) return false;
  for (int c = 0; c < count; ++c) poly[c] = {corners[c]};
  const Vector3& m = inc.faces[j].normal;
  const Vector3 incident_normal = {Dot(m, u), Dot(m, v), Dot(m, face.normal)};
  for (int s = 0; s < sides && count > 0; ++s) {
    const Vector3& p = side[s];
    const Vector3& q = side[(s + 1) % sides];
    const double a = q[1] - p[1], b = p[0] - q[0];  // outward, counterclockwise
    count = geometry::Clip(poly.data(), count, a, b, a * p[0] + b * p[1], s, incident_normal,
                           next.data());
    std::swap(poly, next);
  }
  const geometry::Patch patch =
      geometry::PatchBelow(poly.data(), count, margin, merge, kMaxPolytopePoints);
  // the contact's normal is the face's (a's) or its opposite (b's)
  const double towards_b = Dot(face.normal, out->normal) > 0 ? 1.0 : -1.0;
  for (int c = 0; c < patch.count; ++c) {
    const Vector3& x = patch.p[c];
    const Vector3& g = patch.gradient[c];
    const Vector3 in_plane = Add(f, Add(Scale(u, x[0]), Scale(v, x[1])));
    BoxPoint& point = out->points[c];
    point.pos = Add(in_plane, Scale(face.normal, 0.5 * x[2]));
    point.depth = -x[2];
    point.weight = patch.weight[c];
    const Vector3 world = Add(Add(Scale(u, g[0]), Scale(v, g[1])), Scale(face.normal, g[2]));
    point.gradient = Scale(world, towards_b);
  }
  out->count = patch.count;
  return true;
}

// The edge of hull along direction d that reaches furthest along n.
int SupportEdge(const Hull& hull, int d, const Vector3& n) {
  const Polytope& p = *hull.polytope;
  int best = -1;
  double reach = -HUGE_VAL;
  for (int e = 0; e < hull.edge_count; ++e) {
    if (hull.edges[e].direction != d) continue;
    const double r = Dot(n, Add(p.vertices[hull.edges[e].v0], p.vertices[hull.edges[e].v1]));
    if (r > reach) {
      reach = r;
      best = e;
    }
  }
  return best;
}

// The centre, unit direction and half length of edge e.
void EdgeLine(const Hull& hull, int e, Vector3* centre, Vector3* direction, double* half) {
  const Vector3& p = hull.polytope->vertices[hull.edges[e].v0];
  const Vector3& q = hull.polytope->vertices[hull.edges[e].v1];
  *centre = Scale(Add(p, q), 0.5);
  const Vector3 d = Sub(q, p);
  *half = 0.5 * Norm(d);
  *direction = Scale(d, 0.5 / *half);
}

// The edge-edge contact: the middle of the closest points of a's edge along
// its direction i furthest towards b and b's along j furthest towards a.
void EdgeContact(const Hull& a, int i, const Hull& b, int j, const Vector3& normal, double margin,
                 PolytopeContact* out) {
  Vector3 ca, da, cb, db, pa, pb;
  double ha, hb;
  EdgeLine(a, SupportEdge(a, i, normal), &ca, &da, &ha);
  EdgeLine(b, SupportEdge(b, j, Scale(normal, -1)), &cb, &db, &hb);
  geometry::ClosestOnEdges(ca, da, ha, cb, db, hb, &pa, &pb);
  const double depth = Dot(Sub(pa, pb), normal);
  if (!(depth > -margin)) return;
  out->points[0] = {Scale(Add(pa, pb), 0.5), depth, 1.0, normal};
  out->count = 1;
}

}  // namespace

Polytope PolytopeOfBox(const OrientedBox& box) {
  Polytope p;
  p.vertex_count = 8;
  for (int c = 0; c < 8; ++c) {
    Vector3 x = box.centre;
    for (int i = 0; i < 3; ++i) {
      const double s = (c >> i) & 1 ? box.half[i] : -box.half[i];
      x = Add(x, Scale({box.rotation[i], box.rotation[3 + i], box.rotation[6 + i]}, s));
    }
    p.vertices[c] = x;
  }
  // two triangles per face; corner c has bit i set where it is at +half[i]
  constexpr int kTriangles[12][3] = {{0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3},
                                     {0, 4, 5}, {0, 5, 1}, {2, 3, 7}, {2, 7, 6},
                                     {0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}};
  p.triangle_count = 12;
  for (int t = 0; t < 12; ++t) {
    p.triangles[t] = {kTriangles[t][0], kTriangles[t][1], kTriangles[t][2]};
  }
  return p;
}

PolytopeContact CollidePolytopes(const Polytope& a, const Polytope& b, double margin) {
  PolytopeContact out;
  Hull ha, hb;
  if (!BuildHull(a, &ha) || !BuildHull(b, &hb)) {
    out.feature = PolytopeFeature::kUnsupported;
    return out;
  }
  const Candidate axis = SeparatingAxis(ha, hb);
  if (!(axis.separation < margin)) return out;
  out.feature = axis.feature;
  out.normal = axis.normal;
  const double merge = kBoxPointMergeFraction * std::min(ha.min_half, hb.min_half);
  bool supported = true;
  switch (axis.feature) {
    case PolytopeFeature::kFaceOfA:
      supported = FaceContact(ha, axis.i, hb, margin, merge, &out);
      break;
    case PolytopeFeature::kFaceOfB:
      supported = FaceContact(hb, axis.j, ha, margin, merge, &out);
      break;
    case PolytopeFeature::kEdgeEdge:
      EdgeContact(ha, axis.i, hb, axis.j, axis.normal, margin, &out);
      break;
    default:
      break;
  }
  if (!supported) out.feature = PolytopeFeature::kUnsupported;
  if (out.count == 0 && supported) out.feature = PolytopeFeature::kNone;
  return out;
}

}  // namespace contactlaws
