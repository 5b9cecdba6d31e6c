// Copyright contactlaws authors.
//
// How far MuJoCo 2.2.2's narrowphase can be trusted, per pair of geom types.
//
// For every pair that mjCOLLISIONFUNC collides, two geoms are placed with a
// known overlap and the collision function is called directly. The oracle is
// built by construction: the top geom's lowest point (its support point along
// -z) is put right above the bottom geom's highest point (support along +z),
// `overlap` below it. The penetration depth is then exactly `overlap` along
// +z, as long as the overlap is small against the curvature radii and the
// extents of both geoms (here overlap <= 1e-2 of a 0.1 m size, radii >= 0.05 m).
//
// Each returned contact is also checked on its own: the vertical chord through
// its position crosses the bottom geom's upper surface and the top geom's lower
// surface (closed-form line/geom intersections); the local overlap is the gap
// between them and the exact contact position is the chord's midpoint.
//
// The tests assert the accuracy class measured for each pair type, with the
// faults found asserted as present (BoxBoxReturnsHalfTheOverlap, ...): they
// fail the day MuJoCo changes. NarrowphaseSurvey.PrintsTable prints the
// per-pair summary; NARROWPHASE_SURVEY=full prints every configuration.
//
// Links only MuJoCo and GoogleTest: build/tests/narrowphase_depth_test.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "mujoco/narrowphase_rig.h"

namespace {

using namespace narrowphase_test;  // NOLINT: the test's own helpers

TEST_F(NarrowphaseSurvey, PrintsTable) {
  const char* env = std::getenv("NARROWPHASE_SURVEY");
  const bool contacts = env && std::string(env) == "contacts";
  const bool full = contacts || (env && std::string(env) == "full");
  PrintHeader();
  for (const auto& [b, t] : CollidedPairs()) {
    const std::vector<Measurement> rows = MeasureAll(b, t, contacts);
    ASSERT_FALSE(rows.empty());
    if (full) {
      for (const Measurement& r : rows) PrintRow(r);
      continue;
    }
    // summary: the row with the worst depth error
    const auto worst = std::max_element(rows.begin(), rows.end(), [](auto& x, auto& y) {
      return std::fabs(x.depth_error) < std::fabs(y.depth_error);
    });
    PrintRow(*worst);
  }
}


//---------------------------------- the accuracy class of each pair type ---------------------------

// Closed-form pairs: the error is round-off of positions near 0.1 m, seen
// against a 1e-8 m overlap and amplified by up to ~50 through a 1-degree tilt
// (measured worst 4.1e-8, plane-cylinder tilt1).
constexpr double kRoundOffRel = 1e-6;

// Mesh vertices are stored as float: each coordinate near 0.1 m is off by up
// to half a float ulp (3.7e-9 m), and a depth involves two of them.
constexpr double kFloatVertexAbs = 1e-8;

// A ratio asserted exactly (box-box's halving): only round-off around it.
constexpr double kRatioTol = 1e-6;

// MPR (libccd) stops when its portal moves by less than opt.mpr_tolerance
// (1e-6 m by default): below it the depth is not resolved at all.
constexpr double kMprTolerance = 1e-6;

TEST_F(Narrowphase, ClosedFormPairsAreExactToRoundOff) {
  const std::pair<int, int> exact[] = {
      {mjGEOM_PLANE, mjGEOM_SPHERE},    {mjGEOM_PLANE, mjGEOM_CAPSULE},
      {mjGEOM_PLANE, mjGEOM_ELLIPSOID}, {mjGEOM_PLANE, mjGEOM_CYLINDER},
      {mjGEOM_PLANE, mjGEOM_BOX},       {mjGEOM_SPHERE, mjGEOM_SPHERE},
      {mjGEOM_SPHERE, mjGEOM_CAPSULE},  {mjGEOM_SPHERE, mjGEOM_BOX},
      {mjGEOM_CAPSULE, mjGEOM_CAPSULE}, {mjGEOM_CAPSULE, mjGEOM_BOX},
      {mjGEOM_HFIELD, mjGEOM_BOX}};  // hfield-box: MPR between polytopes lands on a face
  for (const auto& [b, t] : exact) {
    for (const Measurement& r : Rows(b, t)) {
      EXPECT_GE(r.ncon, 1) << r.pair << " " << r.config << " " << r.fraction;
      EXPECT_LT(std::fabs(r.depth_error), kRoundOffRel) << r.pair << " " << r.config << " "
                                                        << r.fraction;
    }
  }
}

TEST_F(Narrowphase, MeshDepthIsExactToFloatVertices) {
  // plane-mesh takes vertices; box-mesh and mesh-mesh go through MPR, which
  // lands exactly on polytope faces
  for (const auto& [b, t] : {std::pair{mjGEOM_PLANE, mjGEOM_MESH}, {mjGEOM_BOX, mjGEOM_MESH},
                             {mjGEOM_MESH, mjGEOM_MESH}}) {
    for (const Measurement& r : Rows(b, t)) {
      EXPECT_GE(r.ncon, 1) << r.pair << " " << r.config << " " << r.fraction;
      EXPECT_LT(std::fabs(r.depth - r.exact), kFloatVertexAbs) << r.pair << " " << r.config;
    }
  }
  // and the float error is visible: 0.05f - 0.05 = 7.45e-10 m on a 1e-8 m overlap
  const Measurement r = Row(mjGEOM_PLANE, mjGEOM_MESH, "face", 1e-7);
  EXPECT_NEAR(r.depth_error, 0.0745, 0.001);
}

TEST_F(Narrowphase, PlaneMeshReturnsThreeOfFourCorners) {
  // mjc_PlaneConvex stops at maxplanemesh = 3 contacts: a flat box mesh
  // rests on 3 corners, so the contact force has a torque about the centre
  EXPECT_EQ(Row(mjGEOM_PLANE, mjGEOM_MESH, "face", 1e-3).ncon, 3);
  EXPECT_EQ(Row(mjGEOM_PLANE, mjGEOM_BOX, "face", 1e-3).ncon, 4);
}

TEST_F(Narrowphase, BoxBoxReturnsHalfTheOverlap) {
  // the face path of mjc_BoxBox halves the point's depth (so that pos is
  // midway) and then reports the halved value as dist
  for (const char* config : {"face", "offset", "corner", "tilt1", "tilt5", "tilt20", "rot45z",
                             "cross90"}) {
    for (double f : kOverlapFractions) {
      const Measurement r = Row(mjGEOM_BOX, mjGEOM_BOX, config, f);
      EXPECT_NEAR(r.depth / r.exact, 0.5, kRatioTol) << config << " " << f;
    }
  }
}

TEST_F(Narrowphase, BoxBoxEdgePathGivesTheFullOverlap) {
  // edge-edge contacts go through the other path, which reports full depths
  for (double f : kOverlapFractions) {
    EXPECT_LT(std::fabs(Row(mjGEOM_BOX, mjGEOM_BOX, "crossed", f).depth_error), kRoundOffRel);
  }
  // a box on its edge switches between the two paths with the overlap
  EXPECT_LT(std::fabs(Row(mjGEOM_BOX, mjGEOM_BOX, "edge", 1e-5).depth_error), kRoundOffRel);
  EXPECT_NEAR(Row(mjGEOM_BOX, mjGEOM_BOX, "edge", 1e-3).depth_error, -0.5, kRatioTol);
}


TEST_F(Narrowphase, BoxBoxDuplicatesCornersOfAlignedFaces) {
  // two equal aligned boxes: 9 contacts at 4 distinct corners
  const std::vector<mjContact> con =
      Contacts(mjGEOM_BOX, mjGEOM_BOX, FindConfig(mjGEOM_BOX, mjGEOM_BOX, "face"), 1e-3);
  std::vector<Vec3> distinct;
  for (const mjContact& c : con) {
    const Vec3 p = {c.pos[0], c.pos[1], c.pos[2]};
    if (std::none_of(distinct.begin(), distinct.end(),
                     [&](const Vec3& q) { return Norm(Sub(p, q)) < 1e-12; })) {
      distinct.push_back(p);
    }
  }
  EXPECT_EQ(con.size(), 9u);
  EXPECT_EQ(distinct.size(), 4u);
}

TEST_F(Narrowphase, BoxBoxEmitsAContactOutsideTheFace) {
  // the top box turned 45 degrees about the vertical: its nearest corner is
  // always emitted, even where it hangs beyond the bottom box's face
  const std::vector<mjContact> con =
      Contacts(mjGEOM_BOX, mjGEOM_BOX, FindConfig(mjGEOM_BOX, mjGEOM_BOX, "rot45z"), 1e-3);
  const Vec3 half = GeomSize(mjGEOM_BOX);
  double beyond = 0;
  for (const mjContact& c : con) {
    beyond = std::max({beyond, std::fabs(c.pos[0]) - half[0], std::fabs(c.pos[1]) - half[1]});
  }
  EXPECT_GT(beyond, 0.04);  // 4.7 cm beyond the face, reported as penetrating
}

TEST_F(Narrowphase, MprMissesOverlapsBelowItsTolerance) {
  // smooth pairs through libccd: an overlap of 1e-8 m (below mpr_tolerance)
  // returns no contact at all, 1e-6 m comes back tens of percent short
  const std::pair<int, int> mpr[] = {
      {mjGEOM_SPHERE, mjGEOM_ELLIPSOID},    {mjGEOM_SPHERE, mjGEOM_CYLINDER},
      {mjGEOM_SPHERE, mjGEOM_MESH},         {mjGEOM_CAPSULE, mjGEOM_ELLIPSOID},
      {mjGEOM_CAPSULE, mjGEOM_CYLINDER},    {mjGEOM_CAPSULE, mjGEOM_MESH},
      {mjGEOM_ELLIPSOID, mjGEOM_ELLIPSOID}, {mjGEOM_ELLIPSOID, mjGEOM_CYLINDER},
      {mjGEOM_ELLIPSOID, mjGEOM_BOX},       {mjGEOM_ELLIPSOID, mjGEOM_MESH},
      {mjGEOM_HFIELD, mjGEOM_SPHERE},       {mjGEOM_HFIELD, mjGEOM_ELLIPSOID}};
  PairRig defaults(mjGEOM_SPHERE, mjGEOM_ELLIPSOID);
  ASSERT_TRUE(defaults.ok());
  ASSERT_EQ(defaults.model()->opt.mpr_tolerance, kMprTolerance);
  for (const auto& [b, t] : mpr) {
    int missed = 0;
    double worst_micron = 0;
    for (const Measurement& r : Rows(b, t)) {
      if (r.fraction == 1e-7 && r.ncon == 0) ++missed;
      if (r.fraction == 1e-5) worst_micron = std::max(worst_micron, std::fabs(r.depth_error));
    }
    const std::string pair = std::string(TypeName(b)) + "-" + TypeName(t);
    EXPECT_GT(missed, 0) << pair;
    EXPECT_GT(worst_micron, 0.05) << pair;
  }
}

TEST_F(Narrowphase, MprOverestimatesWhenTheCentresAreOffTheNormal) {
  // MPR searches along the line between the centres: a tilted box whose
  // corner touches an ellipsoid's top is 46% too deep at a 1 mm overlap
  EXPECT_GT(Row(mjGEOM_ELLIPSOID, mjGEOM_BOX, "tilt5", 1e-2).depth_error, 0.4);
  EXPECT_GT(Row(mjGEOM_SPHERE, mjGEOM_CYLINDER, "tilt1", 1e-2).depth_error, 0.15);
}

}  // namespace
