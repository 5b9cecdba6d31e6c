// Copyright contactlaws authors.
//
// The box-box contact against closed forms: two boxes placed with a known
// overlap (from 1e-7 to 1e-2 of the size), face on face (aligned, offset,
// turned 45 degrees), tilted 1-20 degrees, on an edge, on a corner, edge
// across edge. Every point's depth is the exact one, no point is repeated,
// and every point lies on the overlap region, its two witness points on the
// two surfaces. Links the geometry layer alone (no MuJoCo).

#include "geometry/box_box.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/box_scenes.h"

namespace contactlaws {
namespace {

using namespace box_scenes;  // NOLINT: the scenes' vocabulary

// Size every overlap is a fraction of: the largest half size.
constexpr double kSize = 0.1;
constexpr double kOverlapFractions[] = {1e-7, 1e-5, 1e-3, 1e-2};

// Depths and positions are differences of coordinates near 0.1 m, each
// carrying ~1e-17 m of round-off through a few dozen operations: 1e-13 m is
// 1e-5 of the smallest overlap (1e-8 m) and far above the round-off.
constexpr double kTolerance = 1e-13;

// Signed distance of p to the box (negative inside).
double SignedDistance(const OrientedBox& box, const Vector3& p) {
  const Vector3 o = ApplyTransposed(box.rotation, Sub(p, box.centre));
  Vector3 q, out;
  for (int i = 0; i < 3; ++i) {
    q[i] = std::fabs(o[i]) - box.half[i];
    out[i] = std::max(q[i], 0.0);
  }
  return Norm(out) + std::min(std::max({q[0], q[1], q[2]}), 0.0);
}

// What every contact must satisfy: at most 8 points, none repeated, each
// with its witness points (pos +- normal depth/2) on the two surfaces, the
// incident one inside the reference box; a unit normal.
void ExpectWellFormed(const OrientedBox& a, const OrientedBox& b, const BoxBoxContact& c) {
  ASSERT_LE(c.count, kMaxBoxBoxPoints);
  if (c.count == 0) return;
  EXPECT_NEAR(Norm(c.normal), 1, kTolerance);
  const double merge = kBoxPointMergeFraction * std::min({a.half[0], a.half[1], a.half[2],
                                                          b.half[0], b.half[1], b.half[2]});
  for (int i = 0; i < c.count; ++i) {
    const BoxPoint& p = c.points[i];
    const Vector3 on_a = Add(p.pos, Scale(c.normal, 0.5 * p.depth));
    const Vector3 on_b = Sub(p.pos, Scale(c.normal, 0.5 * p.depth));
    EXPECT_NEAR(SignedDistance(a, on_a), 0, kTolerance) << "point " << i;
    EXPECT_NEAR(SignedDistance(b, on_b), 0, kTolerance) << "point " << i;
    // the incident box's witness is in the reference box (on the overlap
    // region); apart within a margin, it is at most the gap outside
    const double slack = kTolerance + std::max(0.0, -p.depth);
    if (c.feature != BoxFeature::kFaceOfB) {
      EXPECT_LT(SignedDistance(a, on_b), slack) << "point " << i;
    }
    if (c.feature != BoxFeature::kFaceOfA) {
      EXPECT_LT(SignedDistance(b, on_a), slack) << "point " << i;
    }
    for (int j = 0; j < i; ++j) {
      EXPECT_GT(Norm(Sub(p.pos, c.points[j].pos)), merge) << "points " << j << ", " << i;
    }
  }
  // the weights: an edge crossing's one point 1; a face patch's points
  // share 4 with the vertices at the plane (each a turn of the polygon)
  double total = 0;
  for (int i = 0; i < c.count; ++i) {
    EXPECT_GT(c.points[i].weight, 0) << "point " << i;
    total += c.points[i].weight;
  }
  if (c.feature == BoxFeature::kEdgeEdge) {
    EXPECT_EQ(c.points[0].weight, 1);
  } else {
    EXPECT_LE(total, 4 + kTolerance);
  }
}

// The weights of c's points, in order, are expected (within tolerance: the
// turns of a polygon of round-off-exact vertices).
void ExpectWeights(const BoxBoxContact& c, double expected) {
  for (int i = 0; i < c.count; ++i) EXPECT_NEAR(c.points[i].weight, expected, 1e-9) << i;
}

// Each expected point is found once, at its position and depth.
void ExpectPoints(const BoxBoxContact& c, const std::vector<BoxPoint>& expected) {
  ASSERT_EQ(c.count, static_cast<int>(expected.size()));
  for (const BoxPoint& e : expected) {
    const auto* found = std::find_if(c.points.begin(), c.points.begin() + c.count,
                                     [&](const BoxPoint& p) {
                                       return Norm(Sub(p.pos, e.pos)) < 1e3 * kTolerance;
                                     });
    ASSERT_NE(found, c.points.begin() + c.count)
        << "no point at " << e.pos[0] << " " << e.pos[1] << " " << e.pos[2];
    EXPECT_NEAR(found->depth, e.depth, kTolerance);
    EXPECT_LT(Norm(Sub(found->pos, e.pos)), kTolerance);
  }
}

const OrientedBox kBase{{0, 0, 0}, kIdentity, {0.1, 0.08, 0.05}};
const OrientedBox kWideBase{{0, 0, 0}, kIdentity, {0.3, 0.3, 0.05}};
const Vector3 kCube = {0.05, 0.05, 0.05};

// Points at the corners of the rectangle [x0, x1] x [y0, y1], midway at z.
std::vector<BoxPoint> Rectangle(double x0, double x1, double y0, double y1, double z,
                                double depth) {
  return {{{x0, y0, z}, depth}, {{x1, y0, z}, depth}, {{x1, y1, z}, depth},
          {{x0, y1, z}, depth}};
}

TEST(BoxBoxTest, AlignedFacesGiveTheFourCornersAtFullDepth) {
  for (const double f : kOverlapFractions) {
    const double d = f * kSize;
    const OrientedBox b = Above(kBase, kIdentity, kBase.half, d);
    const BoxBoxContact c = CollideBoxes(kBase, b, 0);
    ExpectWellFormed(kBase, b, c);
    EXPECT_EQ(c.feature, BoxFeature::kFaceOfA);
    EXPECT_NEAR(c.normal[2], 1, kTolerance);
    ExpectPoints(c, Rectangle(-0.1, 0.1, -0.08, 0.08, 0.05 - d / 2, d));
    ExpectWeights(c, 1);
  }
}

TEST(BoxBoxTest, NearlyAlignedFacesGiveEachCornerOnce) {
  // equal boxes, one turned by 1e-6 degrees: each corner that pokes out of
  // the other face by ~1e-9 m is clipped into two points ~1e-9 m apart, each
  // with half the corner's turn: together they weigh one corner, as the
  // aligned boxes' corner does (the patch's force does not jump with a turn)
  for (const double f : kOverlapFractions) {
    const double d = f * kSize;
    const OrientedBox b = Above(kBase, Rotation({0, 0, 1}, 1e-6), kBase.half, d);
    const BoxBoxContact c = CollideBoxes(kBase, b, 0);
    ExpectWellFormed(kBase, b, c);
    double at_corner[2][2] = {{0, 0}, {0, 0}};
    for (int i = 0; i < c.count; ++i) {
      EXPECT_NEAR(c.points[i].depth, d, kTolerance);
      at_corner[c.points[i].pos[0] > 0][c.points[i].pos[1] > 0] += c.points[i].weight;
    }
    // the turns of the 8 vertices: 1e-6 degrees off the square's quarters
    constexpr double kTurnTolerance = 1e-7;
    for (const auto& row : at_corner) {
      for (const double w : row) EXPECT_NEAR(w, 1, kTurnTolerance);
    }
  }
}

TEST(BoxBoxTest, OffsetFacesGiveTheOverlapRectangle) {
  // offset by 15% of each side
  const double dx = 0.15 * 0.2, dy = 0.15 * 0.16;
  for (const double f : kOverlapFractions) {
    const double d = f * kSize;
    const OrientedBox b = Above(kBase, kIdentity, kBase.half, d, dx, dy);
    const BoxBoxContact c = CollideBoxes(kBase, b, 0);
    ExpectWellFormed(kBase, b, c);
    ExpectPoints(c, Rectangle(-0.1 + dx, 0.1, -0.08 + dy, 0.08, 0.05 - d / 2, d));
  }
}

TEST(BoxBoxTest, FacesTurned45DegreesGiveTheOctagon) {
  // two equal squares, one turned 45 degrees: the regular octagon of
  // inradius h, its vertices at 22.5 + 45 k degrees
  const OrientedBox a{{0, 0, 0}, kIdentity, kCube};
  const double h = kCube[0];
  for (const double f : kOverlapFractions) {
    const double d = f * kSize;
    const OrientedBox b = Above(a, Rotation({0, 0, 1}, 45), kCube, d);
    const BoxBoxContact c = CollideBoxes(a, b, 0);
    ExpectWellFormed(a, b, c);
    std::vector<BoxPoint> octagon;
    for (int k = 0; k < 8; ++k) {
      const double angle = (22.5 + 45 * k) * kPi / 180;
      const double r = h / std::cos(22.5 * kPi / 180);
      octagon.push_back({{r * std::cos(angle), r * std::sin(angle), h - d / 2}, d});
    }
    ExpectPoints(c, octagon);
    ExpectWeights(c, 0.5);  // the octagon's turns: 45 degrees each
  }
}

TEST(BoxBoxTest, TiltedBoxGivesItsCornersExactDepths) {
  // a cube tilted about a generic horizontal axis on a wider box: its bottom
  // face's corners, each at the depth its height below the top face gives
  const Vector3 axis = {std::cos(kPi / 6), std::sin(kPi / 6), 0};
  for (const double degrees : {1.0, 5.0, 10.0, 20.0}) {
    for (const double d : {1e-8, 1e-6, 1e-4, 1e-3, 3e-3, 2e-2, 4e-2}) {
      const OrientedBox b = Above(kWideBase, Rotation(axis, degrees), kCube, d);
      const BoxBoxContact c = CollideBoxes(kWideBase, b, 0);
      ExpectWellFormed(kWideBase, b, c);
      std::vector<BoxPoint> corners;
      for (const double u : {-1.0, 1.0}) {
        for (const double v : {-1.0, 1.0}) {
          const Vector3 p = Add(b.centre, Apply(b.rotation, {u * 0.05, v * 0.05, -0.05}));
          const double depth = 0.05 - p[2];
          if (depth > 0) corners.push_back({{p[0], p[1], p[2] + depth / 2}, depth});
        }
      }
      SCOPED_TRACE(testing::Message() << degrees << " deg, overlap " << d);
      ExpectPoints(c, corners);
    }
  }
}

TEST(BoxBoxTest, IssueExampleTiltedOneDegree) {
  // issue 11: tilted by 1 degree, a corner 1.73 mm in, reported by MuJoCo
  // 2.2.2 as 0.000865; here the full 1.73 mm
  const OrientedBox b = Above(kWideBase, Rotation({1, 1, 0}, 1), kCube, 1.73e-3);
  const BoxBoxContact c = CollideBoxes(kWideBase, b, 0);
  ExpectWellFormed(kWideBase, b, c);
  ASSERT_GE(c.count, 1);
  double deepest = 0;
  for (int i = 0; i < c.count; ++i) deepest = std::max(deepest, c.points[i].depth);
  EXPECT_NEAR(deepest, 1.73e-3, kTolerance);
}

// Box b of a's size turned by yaw degrees about z, then tilted by tilt rad
// about a horizontal axis at angle heading, its centre over (x, y) and its
// lowest corner overlap below a's top face.
OrientedBox Landing(const OrientedBox& a, double yaw, double tilt, double heading, double overlap,
                    double x, double y) {
  OrientedBox b{{x, y, 0}, LandingAttitude(yaw, tilt, heading), a.half};
  b.centre[2] = a.centre[2] + a.half[2] - overlap - Lowest(b)[2];
  return b;
}

TEST(BoxBoxTest, ABoxLandingTurnedAndBarelyTiltedGivesAPatch) {
  // box_stack's top box landing at a 2 ms step: turned 50 degrees, tilted
  // 3e-3 rad, its lowest corner 0.18 mm down and overhanging. Along an edge
  // pair's axis the boxes overlap less than along the face normal, and the
  // least overlap alone carried the landing box on one point of that edge
  // crossing; the faces touch over a patch: the lower box's top face clips
  // the upper one's bottom face, each point at its own depth.
  const OrientedBox a{{0, 0, 0}, kIdentity, kCube};
  const OrientedBox b = Landing(a, 50.2889, 3.0861e-3, 0.3, 1.83184e-4, 3.58774e-3, -8.32184e-3);
  const BoxBoxContact c = CollideBoxes(a, b, 0);
  ExpectWellFormed(a, b, c);
  EXPECT_NE(c.feature, BoxFeature::kEdgeEdge);  // either box's face
  EXPECT_GE(c.count, 3);
  EXPECT_GE(c.normal[2], std::cos(3.0861e-3) - 1e-12);  // a face normal, up or tilted
}

TEST(BoxBoxTest, NearlyParallelFacesNeverTouchOnAnEdgeCrossing) {
  // 20,000 landings of equal boxes, turned anyhow, tilted 1e-3 to 0.3 rad,
  // up to 0.5 mm deep, off centre by up to 3 cm: below 0.1 rad of tilt
  // (kParallelFaceSine) the contact is a face's, and every contact is well
  // formed (its points on both surfaces, within the overlap)
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> u(0, 1);
  const OrientedBox a{{0, 0, 0}, kIdentity, kCube};
  int patches = 0, edges = 0;
  for (int k = 0; k < 20000; ++k) {
    const double tilt = std::pow(10.0, -3 + 2.5 * u(random));
    const OrientedBox b = Landing(a, 90 * u(random), tilt, 2 * kPi * u(random),
                                  1e-5 + 5e-4 * u(random), 0.06 * (u(random) - 0.5),
                                  0.06 * (u(random) - 0.5));
    const BoxBoxContact c = CollideBoxes(a, b, 0);
    ExpectWellFormed(a, b, c);
    if (tilt < 0.0995) {
      ASSERT_NE(c.feature, BoxFeature::kEdgeEdge) << k;
      patches += c.count >= 3;
    } else {
      edges += c.feature == BoxFeature::kEdgeEdge;
    }
  }
  EXPECT_GT(patches, 5000);  // most landings below 0.1 rad rest on a patch
  // steeper, edge crossings remain what they are (73 of ~4,000), unless the
  // edge lies within 0.1 rad of the face it crosses (EdgeAlongFace)
  EXPECT_GT(edges, 30);
}

// The patch's elastic energy for a law of exponent 1.5: sum of weight x
// d^2.5 (the law's U(d) up to its constant).
double PatchEnergy(const BoxBoxContact& c) {
  double energy = 0;
  for (int i = 0; i < c.count; ++i) {
    energy += c.points[i].weight * std::pow(std::max(c.points[i].depth, 0.0), 2.5);
  }
  return energy;
}

TEST(BoxBoxTest, ThePatchsEnergyIsContinuousInThePose) {
  // a cube turned 30 degrees and tilted 0.03 rad (a face contact), its
  // lowest corner 1 mm below a box's top face, slid along x off its edge in
  // 10 um steps: its corners cross the box's side planes while deep, the
  // polygon's vertices split and merge, the plane's cut moves over the
  // patch. At the largest jump of the energy between two poses, steps 1,000
  // times shorter must give a jump ~1,000 times smaller: the energy has no
  // step there. (A full penalty per clipped vertex, not cut by the plane,
  // kept a jump of a whole point's energy however short the step: 3.2e-8
  // at both step lengths, measured; now 7.8e-11 and 7.8e-14.)
  const auto energy = [&](double x) {
    OrientedBox b{{x, 0.01, 0}, LandingAttitude(30, 0.03, 0.4), kCube};
    b.centre[2] = kBase.half[2] - 1e-3 - Lowest(b)[2];
    const BoxBoxContact c = CollideBoxes(kBase, b, 0);
    EXPECT_NE(c.feature, BoxFeature::kEdgeEdge) << x;
    return PatchEnergy(c);
  };
  constexpr double kStep = 1e-5;  // m
  double worst = 0, at = 0;
  for (double x = 0; x < 0.14; x += kStep) {
    const double jump = std::abs(energy(x + kStep) - energy(x));
    if (jump > worst) {
      worst = jump;
      at = x;
    }
  }
  ASSERT_GT(worst, 0);
  double finest = 0;
  for (double x = at; x < at + kStep; x += kStep / 1000) {
    finest = std::max(finest, std::abs(energy(x + kStep / 1000) - energy(x)));
  }
  // Lipschitz: 1/1000 of the worst jump, with a factor 10 for the slope's
  // change within the step
  EXPECT_LT(finest, 1e-2 * worst) << "at x = " << at;
}

TEST(BoxBoxTest, EdgeOnFaceGivesTheEdgeEndsAtFullDepth) {
  const double h = kCube[0];
  for (const double f : kOverlapFractions) {
    const double d = f * kSize;
    const OrientedBox b = Above(kWideBase, Rotation({1, 0, 0}, 45), kCube, d);
    const BoxBoxContact c = CollideBoxes(kWideBase, b, 0);
    ExpectWellFormed(kWideBase, b, c);
    ExpectPoints(c, {{{-h, 0, 0.05 - d / 2}, d}, {{h, 0, 0.05 - d / 2}, d}});
    ExpectWeights(c, 1);  // the strip's corners below the plane
  }
}

TEST(BoxBoxTest, CornerOnFaceGivesOnePoint) {
  const Matrix corner = Multiply(Rotation({0, 1, 0}, 35.26438968275465), Rotation({1, 0, 0}, 45));
  for (const double f : kOverlapFractions) {
    const double d = f * kSize;
    const OrientedBox b = Above(kWideBase, corner, kCube, d);
    const BoxBoxContact c = CollideBoxes(kWideBase, b, 0);
    ExpectWellFormed(kWideBase, b, c);
    ExpectPoints(c, {{{0, 0, 0.05 - d / 2}, d}});
    // the corner's turn in the triangle below the plane: its two edges on
    // the incident face, 120 degrees apart seen from above, turn by 60
    ExpectWeights(c, 4.0 / 6);
  }
}

TEST(BoxBoxTest, CrossedEdgesGiveOnePointAtFullDepth) {
  // a's top ridge along y, b's bottom ridge along x, crossing at the origin
  const double ridge = 0.05 * std::sqrt(2.0);
  const OrientedBox a{{0, 0, 0}, Rotation({0, 1, 0}, 45), kCube};
  for (const double f : kOverlapFractions) {
    const double d = f * kSize;
    const OrientedBox b{{0, 0, 2 * ridge - d}, Rotation({1, 0, 0}, 45), kCube};
    const BoxBoxContact c = CollideBoxes(a, b, 0);
    ExpectWellFormed(a, b, c);
    EXPECT_EQ(c.feature, BoxFeature::kEdgeEdge);
    EXPECT_NEAR(c.normal[2], 1, kTolerance);
    ExpectPoints(c, {{{0, 0, ridge - d / 2}, d}});
  }
}

TEST(BoxBoxTest, BoxesApartWithinTheMarginGiveTheGap) {
  const double gap = 1e-3;
  const OrientedBox b = Above(kBase, kIdentity, kBase.half, -gap);
  EXPECT_EQ(CollideBoxes(kBase, b, 0).count, 0);
  EXPECT_EQ(CollideBoxes(kBase, b, gap / 2).count, 0);
  const BoxBoxContact c = CollideBoxes(kBase, b, 2 * gap);
  ExpectWellFormed(kBase, b, c);
  ExpectPoints(c, Rectangle(-0.1, 0.1, -0.08, 0.08, 0.05 + gap / 2, -gap));
}

TEST(BoxBoxTest, NormalPointsFromAToBWhicheverBoxIsBelow) {
  const OrientedBox b = Above(kBase, kIdentity, kBase.half, 1e-4);
  const BoxBoxContact up = CollideBoxes(kBase, b, 0);
  const BoxBoxContact down = CollideBoxes(b, kBase, 0);
  EXPECT_NEAR(up.normal[2], 1, kTolerance);
  EXPECT_NEAR(down.normal[2], -1, kTolerance);
  EXPECT_EQ(up.count, down.count);
  ExpectWellFormed(b, kBase, down);
}

TEST(BoxBoxTest, AnyPoseGivesAWellFormedContact) {
  // random poses of two boxes overlapping by up to 1e-2 of the size: the
  // invariants hold whatever the features. std::mt19937's output is fixed by
  // the standard; it is mapped to numbers by hand (distributions are not).
  std::mt19937 random(11);
  const auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(random()) / 4294967296.0;
  };
  int touching = 0;
  for (int n = 0; n < 2000; ++n) {
    const Vector3 half_a = {uniform(0.02, 0.1), uniform(0.02, 0.1), uniform(0.02, 0.1)};
    const Vector3 half_b = {uniform(0.02, 0.1), uniform(0.02, 0.1), uniform(0.02, 0.1)};
    const OrientedBox a{{0, 0, 0},
                        Rotation({uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)},
                                 uniform(0, 180)),
                        half_a};
    const Matrix rb = Rotation({uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)}, uniform(0, 180));
    // b brought along a random direction until it just touches, then pushed in
    const Vector3 dir = Scale(Vector3{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)}, 1.0);
    const Vector3 unit = Scale(dir, 1 / Norm(dir));
    double lo = 0, hi = 1;
    for (int k = 0; k < 100; ++k) {
      const double mid = 0.5 * (lo + hi);
      (CollideBoxes(a, {Scale(unit, mid), rb, half_b}, 0).count > 0 ? lo : hi) = mid;
    }
    const OrientedBox b{Scale(unit, hi - uniform(0, 1e-2) * kSize), rb, half_b};
    const BoxBoxContact c = CollideBoxes(a, b, 0);
    SCOPED_TRACE(testing::Message() << "pose " << n);
    ExpectWellFormed(a, b, c);
    touching += c.count > 0;
  }
  EXPECT_GT(touching, 1900);
}

}  // namespace
}  // namespace contactlaws
