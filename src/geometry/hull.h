// Copyright contactlaws authors.
//
// A polytope's hull as the polytope contact needs it: its distinct faces
// (coplanar triangles merged, outward normals, planes), its hull edges (not
// the diagonals inside a face) and their distinct directions, and its half
// extents. Internal to src/geometry; allocates nothing.

#ifndef CONTACTLAWS_GEOMETRY_HULL_H_
#define CONTACTLAWS_GEOMETRY_HULL_H_

#include <array>

#include "geometry/patch.h"
#include "geometry/polytope.h"

namespace contactlaws {
namespace geometry {

// Each triangle has 3 edges, each shared by 2 triangles.
constexpr int kMaxHullEdges = 3 * kMaxPolytopeTriangles / 2;

struct HullFace {
  Vector3 normal{};   // outward, unit
  double offset = 0;  // the plane: normal . x = offset
};

struct HullEdge {
  int v0 = -1, v1 = -1;  // vertex indices
  int f0 = -1, f1 = -1;  // the faces on either side
  int direction = -1;    // index in Hull::directions
};

struct Hull {
  const Polytope* polytope = nullptr;
  Vector3 centre{};  // the vertices' mean
  int face_count = 0;
  std::array<HullFace, kMaxPolytopeTriangles> faces{};
  int edge_count = 0;
  std::array<HullEdge, kMaxHullEdges> edges{};
  int direction_count = 0;
  std::array<Vector3, kMaxHullEdges> directions{};  // unit, one per parallel set
  double min_half = 0;  // smallest and largest half extent along a face normal
  double max_half = 0;
};

// The hull of p; false if p is degenerate (fewer than 4 faces, or a triangle
// of zero area).
bool BuildHull(const Polytope& p, Hull* hull);

// The extent of the hull's vertices along direction n.
void Extent(const Hull& hull, const Vector3& n, double* low, double* high);

}  // namespace geometry
}  // namespace contactlaws

#endif  // CONTACTLAWS_GEOMETRY_HULL_H_
