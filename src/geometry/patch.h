// Copyright contactlaws authors.
//
// What box_box and polytope share: vector arithmetic, the clipping of a
// polygon by a half-plane of a reference face, the patch of clipped points
// (merged, ordered, simplified), and the closest points of two edges. Pure
// geometry, no MuJoCo types, allocates nothing. Internal to src/geometry.

#ifndef CONTACTLAWS_GEOMETRY_PATCH_H_
#define CONTACTLAWS_GEOMETRY_PATCH_H_

#include <array>
#include <cmath>
#include <cstdint>

namespace contactlaws {

using Vector3 = std::array<double, 3>;

namespace geometry {

inline Vector3 Add(const Vector3& a, const Vector3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vector3 Sub(const Vector3& a, const Vector3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vector3 Scale(const Vector3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double Dot(const Vector3& a, const Vector3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vector3 Cross(const Vector3& a, const Vector3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double Norm(const Vector3& a) { return std::sqrt(Dot(a, a)); }

// The separating-axis test of box_box and polytope. Edge axes of edges
// closer to parallel than this sine are skipped: their cross product,
// normalised, carries round-off amplified by 1/sine, and two nearly parallel
// edges touch as a face contact's clipped edge does.
constexpr double kParallelSine = 1e-3;
// Two faces closer to parallel than this sine (0.1 rad, 5.7 degrees) touch
// over a patch, and the face contact (the incident face clipped by the
// reference face, each point at its own depth) is kept over any edge axis:
// when a corner of one overhangs the other, an edge-pair axis overlaps less
// than the face normal, and the least overlap alone would carry a resting
// box on one point of that edge crossing.
constexpr double kParallelFaceSine = 0.1;
// Whether a reference face and an incident face, the cosine between the
// one's outward normal and the other's inward one, are within
// kParallelFaceSine of parallel: then their contact is the face contact.
inline bool NearlyParallelFaces(double cosine) {
  return cosine > 0 && cosine * cosine >= 1 - kParallelFaceSine * kParallelFaceSine;
}
// An edge pair's axis within kParallelFaceSine of a face's normal: an edge
// of the other body lies nearly flat on that face (the pair's cross product
// is along the normal only when the edge is nearly parallel to the face),
// and it touches along a segment, the face contact's, not at one point. Two
// equal separations along nearly the same axis would otherwise flicker
// between the edge's one point and the face's patch (a domino's top edge
// under another lying on it), and the force with them.
inline bool EdgeAlongFace(const Vector3& edge_axis, const Vector3& face_normal) {
  return NearlyParallelFaces(std::fabs(Dot(edge_axis, face_normal)));
}
// An edge axis, or a face of the second body, replaces the best face of the
// first only when it separates more by this fraction of the largest half
// size: the axes that coincide (the faces of two aligned boxes, and the edge
// products equal to them) differ by round-off, ~1e-16 of the size amplified
// by up to 1/kParallelSine, and the choice must not flicker between them.
constexpr double kAxisTieFraction = 1e-11;

// Room for a clipped polygon: each clip of a convex polygon adds at most one
// vertex; a polytope face of up to 32 vertices clipped by a reference face of
// up to 32 sides stays below 64 (polytope.h's kMaxFaceVertices), a box's
// quadrilateral clipped by 4 sides below 8; round-off on near-degenerate
// input could add more, and is cut at the capacity.
constexpr int kClipCapacity = 64;

// A vertex of a clipped polygon in a reference face's frame (u, v, height
// along the normal), with the gradient of its height: how the height moves
// with a displacement of the incident face relative to the reference face
// (in the same frame), its height component 1. The force that is the
// gradient of a point's elastic energy is along it, so a force along the
// normal alone does work the energy does not store where the gradient has a
// sideways part. An incident corner is a point of the incident face: (0, 0,
// 1). A vertex where an incident edge e crosses a side plane s slides along
// the edge as the faces move: (0, 0, 1) - s e_n / (s . e), perpendicular to
// the edge (the common normal of the edge and the reference face's side).
// A reference face's corner lies on the incident plane, normal m (any
// length): m / m_n, perpendicular to the incident face.
struct ClipVertex {
  Vector3 p{};
  Vector3 gradient{0, 0, 1};
  uint64_t sides = 0;  // the reference face's sides (Clip's side) it lies on, a bit each
};

// Keeps the part of polygon in (n vertices) where a * u + b * v <= h, the
// reference face's side number side (< 64) of an incident face of normal
// incident_normal (in the same frame); writes it to out, returns its count.
int Clip(const ClipVertex* in, int n, double a, double b, double h, int side,
         const Vector3& incident_normal, ClipVertex* out);

// What a face patch's points carry together: the force of this many points
// at its depth. A box resting flat on a face carries its load on 4 points
// at the law's depth, as on a plane (MuJoCo's plane-box gives its 4
// corners), whatever the patch's shape (a rectangle, the 45-degree octagon).
constexpr double kPatchWeight = 4;

// The points of a face patch in the reference face's frame (u, v, height
// along the normal), each with its weight: its share of the patch's force.
struct Patch {
  std::array<Vector3, kClipCapacity> p{};
  std::array<double, kClipCapacity> weight{};
  std::array<Vector3, kClipCapacity> gradient{};  // of its height (ClipVertex)
  int count = 0;
};

// The patch of a clipped polygon (count vertices in the reference face's
// frame, in order around it): the polygon is clipped by the reference plane
// too (height <= 0), so that a point enters and leaves at zero depth where
// the polygon crosses the plane, and each vertex is weighted by its turn
// (the polygon's exterior angle there, in the plane: u, v) over the full
// turn, times kPatchWeight. A vertex that splits in a clip (a corner
// crossing a side plane) shares its turn with its copy (the new edge starts
// at zero length), two that merge (an incident edge passing a reference
// corner) hand theirs on, and the vertices move continuously: the patch's
// elastic energy, the sum of its points' weight times the law's energy at
// their depths, is continuous in the poses. The weights do not depend on
// where the polygon crosses the plane (which moves fast when the faces are
// nearly parallel), only on the faces' relative turn. Vertices closer than
// merge along the polygon are one, the deeper kept (a corner on a side
// plane clipped into two by round-off). The points are the vertices below
// the plane (depth > 0), then, with margin > 0, those of the polygon
// clipped at height margin within margin above it (a gap's, weighted in
// that polygon), at most max_points (a larger patch gives the lightest
// point's weight to its nearest), each kind ordered by angle about its
// centre from the u axis.
Patch PatchBelow(const ClipVertex* clipped, int count, double margin, double merge, int max_points);

// The closest points of two edges, each given by its centre, unit direction
// and half length, whose directions are not parallel (1 - (da.db)^2 > 0).
void ClosestOnEdges(const Vector3& ca, const Vector3& da, double half_a, const Vector3& cb,
                    const Vector3& db, double half_b, Vector3* pa, Vector3* pb);

}  // namespace geometry
}  // namespace contactlaws

#endif  // CONTACTLAWS_GEOMETRY_PATCH_H_
