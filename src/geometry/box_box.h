// Copyright contactlaws authors.
//
// The contact of two oriented boxes: its normal, and the points of the
// contact patch with their full depths. Pure geometry, no MuJoCo types.
//
// Method: the separating-axis test over the 15 axes (3 + 3 face normals, 9
// edge cross products) finds the axis of least overlap. A face axis gives a
// face contact: the face of the other box most opposed to it (the incident
// face) is clipped against the side planes of the reference face; the patch
// is the part of the clipped polygon below the reference plane, represented
// by its vertices, each with its own depth. An edge axis gives one point, the
// middle of the two edges' closest points.
//
// Why the polygon's vertices, up to 8: a penalty law sums per-point forces,
// so the points must span the patch for the force and torque to be right.
// Two convex quadrilaterals intersect in at most 8 vertices (a square turned
// 45 degrees on another: the octagon), so 8 points keep every patch whole;
// fewer would have to drop vertices and move the centre of the forces (a
// box offset on another would lean towards the kept ones). The cost: for
// equal depths the patch's total force grows with its vertex count (4 for
// rectangles, 8 for the octagon); the statics of a resting box are
// d = (m g / (N K))^(1/n) with N that count. Vertices on a straight edge of
// the patch are not counted (kBoxPointMergeFraction).
//
// Conventions: depth > 0 in contact (m); the normal points from box a to box
// b; a point's position is midway between the two surfaces (MuJoCo's).

#ifndef CONTACTLAWS_GEOMETRY_BOX_BOX_H_
#define CONTACTLAWS_GEOMETRY_BOX_BOX_H_

#include <array>

namespace contactlaws {

using Vector3 = std::array<double, 3>;

// A box: its centre, its orientation as a row-major rotation matrix whose
// columns are the box's axes in the world frame (MuJoCo's geom_xmat), and its
// half sizes along those axes (m).
struct OrientedBox {
  Vector3 centre{};
  std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};
  Vector3 half{};
};

// Most points of one box-box contact: the vertices of two clipped
// quadrilaterals.
inline constexpr int kMaxBoxBoxPoints = 8;

// Points closer than this fraction of the smaller box's smallest half size
// are one point (their mean), and a vertex closer than it to the chord of its
// two neighbours is dropped. Clipping a corner that sits on a side plane (two
// equal boxes face to face) yields it twice up to round-off; two equal faces
// turned by e rad about their normal overlap in an octagon whose 4 extra
// vertices sit on the edges' midpoints, ~e h off the chords: counted, they
// would double the patch's force for the slightest turn. So the patch keeps
// 4 points up to a turn of ~1e-3 rad and gets its 8 beyond.
inline constexpr double kBoxPointMergeFraction = 1e-3;

// What decided the contact.
enum class BoxFeature {
  kNone,       // apart by more than the margin
  kFaceOfA,    // a face of box a is the reference face
  kFaceOfB,    // a face of box b is the reference face
  kEdgeEdge,   // an edge of each box
};

struct BoxPoint {
  Vector3 pos{};     // midway between the surfaces, world frame (m)
  double depth = 0;  // along the normal, > 0 overlapping (m)
};

struct BoxBoxContact {
  BoxFeature feature = BoxFeature::kNone;
  Vector3 normal{};  // unit, from a towards b
  int count = 0;
  // in a stable order: by angle about the patch's centre in the reference
  // face, from its first axis
  std::array<BoxPoint, kMaxBoxBoxPoints> points{};
};

// The contact of boxes a and b: the points deeper than -margin (margin >= 0,
// m; a positive margin also reports boxes apart by less than it, with
// negative depths). Allocates nothing.
BoxBoxContact CollideBoxes(const OrientedBox& a, const OrientedBox& b, double margin);

}  // namespace contactlaws

#endif  // CONTACTLAWS_GEOMETRY_BOX_BOX_H_
