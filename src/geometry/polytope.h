// Copyright contactlaws authors.
//
// The contact of two convex polytopes (a box or a mesh's convex hull): its
// normal, and the points of the contact patch with their full depths. Pure
// geometry, no MuJoCo types, allocates nothing. box_box.h's method for any
// convex polytope:
//
// The separating-axis test over the distinct face normals of both and the
// cross products of their distinct hull-edge directions finds the axis of
// least overlap. A face axis gives a face contact: the face of the other
// polytope most opposed to it (incident) is clipped against the sides of the
// reference face and by the reference plane; its vertices below the plane
// are the points, each with its own depth and its weight (geometry/patch.h,
// as for box-box). An edge axis gives one point, the middle of the two edges'
// closest points. A hull's coplanar triangles are one polygonal face.
//
// Conventions, as box_box.h: depth > 0 in contact (m); the normal points
// from a to b; a point is midway between the two surfaces; points closer
// than kBoxPointMergeFraction of the smaller polytope's smallest half extent
// are one point.

#ifndef CONTACTLAWS_GEOMETRY_POLYTOPE_H_
#define CONTACTLAWS_GEOMETRY_POLYTOPE_H_

#include <array>

#include "geometry/box_box.h"

namespace contactlaws {

// Most vertices of a polytope the kernel takes; a larger one is MuJoCo's
// (the caller falls back to its collider). The separating-axis test costs
// (faces + edge directions) x vertices per pair, and a mesh with more hull
// vertices is a rounded shape (a sphere, a cylinder) whose contacts are
// points or lines, not the flat patches this kernel is for.
inline constexpr int kMaxPolytopeVertices = 64;
// A triangulated convex hull of V vertices has 2V - 4 triangles (Euler).
inline constexpr int kMaxPolytopeTriangles = 2 * kMaxPolytopeVertices - 4;
// Most vertices of one polygonal face: an incident face of 32 clipped by a
// reference face of 32 sides stays within patch.h's kClipCapacity (64).
inline constexpr int kMaxFaceVertices = 32;
// Most points of one contact: as box-box's (kMaxBoxBoxPoints), the clipped
// polygon of two quadrilaterals whole; a larger patch (two octagons) keeps
// 8, each dropped point's weight given to its nearest (patch.h, PatchBelow).
inline constexpr int kMaxPolytopePoints = kMaxBoxBoxPoints;

// Two triangles of a hull are one face when their normals differ by less
// than this sine, and a vertex lies on a face when it is within this
// fraction of the polytope's largest extent of its plane. A mesh's vertices
// are floats (MuJoCo's mesh_vert): a face's triangles' normals differ by
// ~1e-7; distinct faces of a hull an author models differ by far more than
// 1e-5 rad (6e-4 degrees).
inline constexpr double kCoplanarSine = 1e-5;

// A polytope: its vertices in the world frame and its hull's triangles
// (vertex indices, any winding: the outward side is found from the centre).
struct Polytope {
  int vertex_count = 0;
  std::array<Vector3, kMaxPolytopeVertices> vertices{};
  int triangle_count = 0;
  std::array<std::array<int, 3>, kMaxPolytopeTriangles> triangles{};
};

enum class PolytopeFeature {
  kNone,         // apart by more than the margin
  kFaceOfA,      // a face of a is the reference face
  kFaceOfB,      // a face of b is the reference face
  kEdgeEdge,     // an edge of each
  kUnsupported,  // beyond the caps or degenerate: use another collider
};

struct PolytopeContact {
  PolytopeFeature feature = PolytopeFeature::kNone;
  Vector3 normal{};  // unit, from a towards b
  int count = 0;
  // in a stable order: by angle about the patch's centre in the reference
  // face, from the direction of its vertex of lowest index
  std::array<BoxPoint, kMaxPolytopePoints> points{};
};

// The polytope of box: its 8 corners and 12 triangles.
Polytope PolytopeOfBox(const OrientedBox& box);

// The contact of polytopes a and b (each within the caps above): the points
// deeper than -margin (margin >= 0, m). Allocates nothing.
PolytopeContact CollidePolytopes(const Polytope& a, const Polytope& b, double margin);

}  // namespace contactlaws

#endif  // CONTACTLAWS_GEOMETRY_POLYTOPE_H_
