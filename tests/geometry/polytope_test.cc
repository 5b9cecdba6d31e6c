// Copyright contactlaws authors.
//
// The polytope contact. Its oracle is the box-box kernel (box_box_test holds
// it to closed forms): a box given as a polytope (8 corners, 12 triangles)
// against another must give CollideBoxes' feature, normal, points and
// depths, face on face (aligned, offset, turned 45 degrees), tilted, on an
// edge, edge across edge, apart. Then closed forms of polytopes no box
// makes: a tetrahedron on a box face, hexagonal prisms on each other (their
// hexagons fans of 4 triangles, merged into one face each). Links the
// geometry layer alone (no MuJoCo).

#include "geometry/polytope.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/box_scenes.h"

namespace contactlaws {
namespace {

using namespace box_scenes;  // NOLINT: the scenes' vocabulary

// Both kernels compute the same differences of coordinates near 0.1 m in
// different orders (a polytope's face centre is the mean of its corners, a
// box's its centre plus a half size): round-off ~1e-17 m through a few dozen
// operations; 1e-13 m is 1e-5 of the smallest overlap here (1e-8 m).
constexpr double kTolerance = 1e-13;
constexpr double kOverlaps[] = {1e-8, 1e-6, 1e-4, 1e-3};  // m

PolytopeFeature FeatureOf(BoxFeature f) {
  switch (f) {
    case BoxFeature::kFaceOfA: return PolytopeFeature::kFaceOfA;
    case BoxFeature::kFaceOfB: return PolytopeFeature::kFaceOfB;
    case BoxFeature::kEdgeEdge: return PolytopeFeature::kEdgeEdge;
    default: return PolytopeFeature::kNone;
  }
}

// The polytope contact of a and b is CollideBoxes': same feature, normal and
// count, each box point found once at its position, depth and weight. The scene is
// what it claims: CollideBoxes finds feature with count points (any if -1).
void ExpectSameAsBoxes(const OrientedBox& a, const OrientedBox& b, const char* scene,
                       BoxFeature feature, int count) {
  const BoxBoxContact boxes = CollideBoxes(a, b, 0);
  const PolytopeContact poly = CollidePolytopes(PolytopeOfBox(a), PolytopeOfBox(b), 0);
  SCOPED_TRACE(scene);
  EXPECT_EQ(boxes.feature, feature);
  if (count >= 0) {
    EXPECT_EQ(boxes.count, count);
  }
  EXPECT_EQ(poly.feature, FeatureOf(boxes.feature));
  ASSERT_EQ(poly.count, boxes.count);
  if (boxes.count > 0) {
    EXPECT_LT(Norm(Sub(poly.normal, boxes.normal)), kTolerance);
  }
  for (int i = 0; i < boxes.count; ++i) {
    const BoxPoint& e = boxes.points[i];
    int found = 0;
    for (int j = 0; j < poly.count; ++j) {
      if (Norm(Sub(poly.points[j].pos, e.pos)) > kTolerance) continue;
      ++found;
      EXPECT_NEAR(poly.points[j].depth, e.depth, kTolerance) << "point " << i;
      // the same polygon's turns (round-off in the angles of short edges)
      EXPECT_NEAR(poly.points[j].weight, e.weight, 1e-9) << "point " << i;
    }
    EXPECT_EQ(found, 1) << "box point " << i << " at " << e.pos[0] << " " << e.pos[1] << " "
                        << e.pos[2];
  }
}

const OrientedBox kBase{{0, 0, 0}, kIdentity, {0.1, 0.08, 0.05}};
const OrientedBox kCubeBase{{0, 0, 0}, kIdentity, {0.05, 0.05, 0.05}};
const Vector3 kSmall = {0.04, 0.03, 0.02};
const Vector3 kCube = {0.05, 0.05, 0.05};

TEST(PolytopeTest, BoxesAsPolytopesGiveTheBoxBoxContact) {
  for (const double d : kOverlaps) {
    ExpectSameAsBoxes(kBase, Above(kBase, kIdentity, kSmall, d), "face", BoxFeature::kFaceOfA, 4);
    ExpectSameAsBoxes(kBase, Above(kBase, kIdentity, kBase.half, d), "equal faces", BoxFeature::kFaceOfA, 4);
    ExpectSameAsBoxes(kBase, Above(kBase, kIdentity, kSmall, d, 0.09, -0.07), "offset", BoxFeature::kFaceOfA, 4);
    ExpectSameAsBoxes(kCubeBase, Above(kCubeBase, Rotation({0, 0, 1}, 45), kCube, d), "octagon", BoxFeature::kFaceOfA, 8);
    ExpectSameAsBoxes(kBase, Above(kBase, Rotation({0, 0, 1}, 30), kSmall, d, 0.05), "turned", BoxFeature::kFaceOfA, 4);
    for (const double tilt : {1.0, 5.0, 20.0}) {
      ExpectSameAsBoxes(kBase, Above(kBase, Rotation({1, 2, 0}, tilt), kSmall, d), "tilted", BoxFeature::kFaceOfA, -1);
    }
    ExpectSameAsBoxes(kBase, Above(kBase, Rotation({1, 0, 0}, 45), kSmall, d), "edge on face", BoxFeature::kFaceOfA, 2);
    const OrientedBox ridge{{0, 0, 0}, Rotation({0, 1, 0}, 45), kCube};
    const OrientedBox top = Above(ridge, Rotation({1, 0, 0}, 45), kCube, 0);
    OrientedBox crossed = top;  // Above puts it on the ridge's box top: lower it
    crossed.centre[2] = std::sqrt(2.0) * 0.05 * 2 - d;
    ExpectSameAsBoxes(ridge, crossed, "edge across edge", BoxFeature::kEdgeEdge, 1);
    ExpectSameAsBoxes(kBase, Above(kBase, Rotation({1, 2, 0}, 5), kSmall, -d), "apart",
                      BoxFeature::kNone, 0);
    // a tilted small box's top corner into a large flat box's bottom face
    const OrientedBox tilted{{0, 0, 0}, Rotation({1, 2, 0}, 10), kSmall};
    OrientedBox lid{{0, 0, 0}, kIdentity, kBase.half};
    lid.centre[2] = -Lowest(tilted)[2] - d + kBase.half[2];  // tilted's top is -its lowest
    ExpectSameAsBoxes(tilted, lid, "corner into a face above", BoxFeature::kFaceOfB, 1);
  }
}

TEST(PolytopeTest, BoxesApartGiveNoContact) {
  const PolytopeContact c = CollidePolytopes(
      PolytopeOfBox(kBase), PolytopeOfBox(Above(kBase, kIdentity, kSmall, -1e-3)), 0);
  EXPECT_EQ(c.feature, PolytopeFeature::kNone);
  EXPECT_EQ(c.count, 0);
}

TEST(PolytopeTest, ATetrahedronOnABoxFaceGivesItsThreeBaseCornersAtTheirDepths) {
  // base corners below the box's top (z = 0.05) by d0 < d1 < d2 (a tilted
  // base), apex above: 3 points, each at its own depth, midway, normal +z
  const double depth[3] = {1e-4, 2e-4, 3e-4};
  const double xy[3][2] = {{0.03, 0}, {-0.015, 0.026}, {-0.015, -0.026}};
  Polytope tetra;
  tetra.vertex_count = 4;
  for (int i = 0; i < 3; ++i) tetra.vertices[i] = {xy[i][0], xy[i][1], 0.05 - depth[i]};
  tetra.vertices[3] = {0, 0, 0.1};
  tetra.triangle_count = 4;
  tetra.triangles = {{{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}};
  const PolytopeContact c = CollidePolytopes(PolytopeOfBox(kBase), tetra, 0);
  EXPECT_EQ(c.feature, PolytopeFeature::kFaceOfA);
  EXPECT_LT(Norm(Sub(c.normal, {0, 0, 1})), kTolerance);
  ASSERT_EQ(c.count, 3);
  for (int i = 0; i < 3; ++i) {
    const Vector3 expected = {xy[i][0], xy[i][1], 0.05 - depth[i] / 2};
    int found = 0;
    for (int j = 0; j < c.count; ++j) {
      if (Norm(Sub(c.points[j].pos, expected)) > kTolerance) continue;
      ++found;
      EXPECT_NEAR(c.points[j].depth, depth[i], kTolerance);
    }
    EXPECT_EQ(found, 1) << "corner " << i;
  }
}

// A hexagonal prism, circumradius r, from z0 to z1, turned by degrees about
// z; each hexagon a fan of 4 triangles, each side 2.
Polytope HexagonalPrism(double r, double z0, double z1, double degrees) {
  Polytope p;
  p.vertex_count = 12;
  for (int k = 0; k < 6; ++k) {
    const double t = (degrees + 60 * k) * kPi / 180;
    p.vertices[k] = {r * std::cos(t), r * std::sin(t), z0};
    p.vertices[6 + k] = {r * std::cos(t), r * std::sin(t), z1};
  }
  int n = 0;
  for (int k = 1; k < 5; ++k) {
    p.triangles[n++] = {0, k, k + 1};
    p.triangles[n++] = {6, 6 + k, 6 + k + 1};
  }
  for (int k = 0; k < 6; ++k) {
    const int k1 = (k + 1) % 6;
    p.triangles[n++] = {k, k1, 6 + k1};
    p.triangles[n++] = {k, 6 + k1, 6 + k};
  }
  p.triangle_count = n;
  return p;
}

TEST(PolytopeTest, AHexagonalPrismOnALargerOneGivesItsSixCorners) {
  for (const double d : kOverlaps) {
    const Polytope base = HexagonalPrism(0.1, -0.05, 0.05, 0);
    const Polytope top = HexagonalPrism(0.05, 0.05 - d, 0.1 - d, 10);
    const PolytopeContact c = CollidePolytopes(base, top, 0);
    EXPECT_EQ(c.feature, PolytopeFeature::kFaceOfA);
    EXPECT_LT(Norm(Sub(c.normal, {0, 0, 1})), kTolerance);
    ASSERT_EQ(c.count, 6);
    for (int k = 0; k < 6; ++k) {
      const Vector3 corner = top.vertices[k];
      int found = 0;
      for (int j = 0; j < c.count; ++j) {
        if (Norm(Sub(c.points[j].pos, {corner[0], corner[1], 0.05 - d / 2})) > kTolerance) continue;
        ++found;
        EXPECT_NEAR(c.points[j].depth, d, kTolerance);
      }
      EXPECT_EQ(found, 1) << "corner " << k;
    }
  }
}

TEST(PolytopeTest, EqualHexagonsTurned30DegreesKeepEightOfTheirTwelveCorners) {
  // the overlap of two equal hexagons turned 30 degrees is the regular
  // dodecagon of the hexagons' inradius r cos 30: its vertices at r cos 30 /
  // cos 15 from the axis. The cap keeps 8 of them, all at the full depth
  const double d = 1e-4, r = 0.05;
  const PolytopeContact c =
      CollidePolytopes(HexagonalPrism(r, -0.05, 0.05, 0), HexagonalPrism(r, 0.05 - d, 0.1, 30), 0);
  ASSERT_EQ(c.count, kMaxPolytopePoints);
  const double inradius = r * std::cos(kPi / 6);
  for (int j = 0; j < c.count; ++j) {
    EXPECT_NEAR(c.points[j].depth, d, kTolerance);
    const double radius = std::hypot(c.points[j].pos[0], c.points[j].pos[1]);
    EXPECT_NEAR(radius, inradius / std::cos(kPi / 12), kTolerance);
  }
}

// p turned by rotation about the origin, then moved by shift.
Polytope Moved(Polytope p, const Matrix& rotation, const Vector3& shift) {
  for (int i = 0; i < p.vertex_count; ++i) {
    p.vertices[i] = Add(Apply(rotation, p.vertices[i]), shift);
  }
  return p;
}

// The signed distance of x from the nearest plane of p's triangles, outward
// positive: 0 on its surface, negative inside.
double PlaneDistance(const Polytope& p, const Vector3& x) {
  Vector3 centre{};
  for (int i = 0; i < p.vertex_count; ++i) centre = Add(centre, Scale(p.vertices[i], 1.0 / p.vertex_count));
  double distance = -HUGE_VAL;
  for (int t = 0; t < p.triangle_count; ++t) {
    const Vector3& o = p.vertices[p.triangles[t][0]];
    Vector3 n = geometry::Cross(Sub(p.vertices[p.triangles[t][1]], o),
                                Sub(p.vertices[p.triangles[t][2]], o));
    n = Scale(n, 1 / Norm(n));
    if (Dot(n, Sub(centre, o)) > 0) n = Scale(n, -1);
    distance = std::max(distance, Dot(n, Sub(x, o)));
  }
  return distance;
}

// body (about the origin) landing on a body whose top face is at height
// top: at attitude, over (x, y), its lowest vertex overlap below top.
Polytope Landed(const Polytope& body, const Matrix& attitude, double top, double overlap,
                double x, double y) {
  Polytope p = Moved(body, attitude, {x, y, 0});
  double lowest = HUGE_VAL;
  for (int i = 0; i < p.vertex_count; ++i) lowest = std::min(lowest, p.vertices[i][2]);
  return Moved(p, kIdentity, {0, 0, top - overlap - lowest});
}

// Every point on both surfaces (each witness within kTolerance of its
// polytope's boundary) and the incident witness within the reference
// polytope; no two points closer than the merge distance.
void ExpectWellFormed(const Polytope& a, const Polytope& b, const PolytopeContact& c,
                      double merge) {
  for (int i = 0; i < c.count; ++i) {
    const BoxPoint& p = c.points[i];
    const Vector3 on_a = Add(p.pos, Scale(c.normal, 0.5 * p.depth));
    const Vector3 on_b = Sub(p.pos, Scale(c.normal, 0.5 * p.depth));
    EXPECT_NEAR(PlaneDistance(a, on_a), 0, kTolerance) << "point " << i;
    EXPECT_NEAR(PlaneDistance(b, on_b), 0, kTolerance) << "point " << i;
    if (c.feature != PolytopeFeature::kFaceOfB) {
      EXPECT_LT(PlaneDistance(a, on_b), kTolerance) << "point " << i;
    }
    if (c.feature != PolytopeFeature::kFaceOfA) {
      EXPECT_LT(PlaneDistance(b, on_a), kTolerance) << "point " << i;
    }
    for (int j = 0; j < i; ++j) {
      EXPECT_GT(Norm(Sub(p.pos, c.points[j].pos)), merge) << "points " << j << ", " << i;
    }
  }
}

// How many vertices of p are inside q (deeper than kTolerance).
int VerticesInside(const Polytope& p, const Polytope& q) {
  int count = 0;
  for (int i = 0; i < p.vertex_count; ++i) count += PlaneDistance(q, p.vertices[i]) < -kTolerance;
  return count;
}

TEST(PolytopeTest, NearlyParallelFacesNeverTouchOnAnEdgeCrossing) {
  // 10,000 landings each of equal cubes and of equal hexagonal prisms,
  // turned anyhow, tilted 1e-3 to 0.3 rad, up to 0.5 mm deep, off centre by
  // up to 3 cm. Below 0.1 rad of tilt (kParallelFaceSine) the contact is a
  // face's, and a contact of one point has at most one corner in the other
  // body (one corner in a face). The least overlap alone put 43% of the
  // cubes' and 26% of the prisms' landings below 0.1 rad on one point of an
  // edge crossing (of 200,000 each), 1 in 6 of the cubes' and 1 in 2 of the
  // prisms' with 2 to 5 corners in. Every contact is well formed.
  const Polytope cube = PolytopeOfBox(kCubeBase);
  const Polytope prism = HexagonalPrism(0.05, -0.05, 0.05, 0);
  const double merge = kBoxPointMergeFraction * 0.05 * std::cos(kPi / 6);  // the prism's inradius
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (const Polytope* shape : {&cube, &prism}) {
    int patches = 0, edges = 0;
    for (int k = 0; k < 10000; ++k) {
      const double tilt = std::pow(10.0, -3 + 2.5 * u(random));
      const Matrix attitude = LandingAttitude(360 * u(random), tilt, 2 * kPi * u(random));
      const double overlap = 1e-5 + 5e-4 * u(random);
      const double x = 0.06 * (u(random) - 0.5), y = 0.06 * (u(random) - 0.5);
      const Polytope b = Landed(*shape, attitude, 0.05, overlap, x, y);
      const PolytopeContact c = CollidePolytopes(*shape, b, 0);
      ExpectWellFormed(*shape, b, c, merge);
      if (tilt < 0.0995) {
        ASSERT_NE(c.feature, PolytopeFeature::kEdgeEdge) << k;
        if (c.count == 1) {
          ASSERT_LE(VerticesInside(b, *shape) + VerticesInside(*shape, b), 1) << k;
        }
        patches += c.count >= 3;
      } else {
        edges += c.feature == PolytopeFeature::kEdgeEdge;
      }
    }
    EXPECT_GT(patches, 2500);  // a third of the landings below 0.1 rad rest on a patch
    // steeper, edge crossings remain what they are (30 and 27 of ~2,000),
    // unless the edge lies within 0.1 rad of the face it crosses
    // (EdgeAlongFace)
    EXPECT_GT(edges, 10);
  }
}

TEST(PolytopeTest, ADegeneratePolytopeIsUnsupported) {
  Polytope flat = PolytopeOfBox({{0, 0, 0}, kIdentity, {0.1, 0.1, 0}});
  const PolytopeContact c = CollidePolytopes(PolytopeOfBox(kBase), flat, 0);
  EXPECT_EQ(c.feature, PolytopeFeature::kUnsupported);
}

}  // namespace
}  // namespace contactlaws
