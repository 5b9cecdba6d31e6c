// Copyright contactlaws authors.
//
// The contact of two oriented boxes: its normal, and the points of the
// contact patch with their full depths. Pure geometry, no MuJoCo types.
//
// Method: the separating-axis test over the 15 axes (3 + 3 face normals, 9
// edge cross products) finds the axis of least overlap. A face axis gives a
// face contact: the face of the other box most opposed to it (the incident
// face) is clipped against the side planes of the reference face and by the
// reference plane; the patch is that polygon, its vertices below the plane
// the points, each with its own depth and a weight, its turn in the polygon
// (geometry/patch.h, PatchBelow). An edge axis gives one point, the middle
// of the two edges' closest points, of weight 1.
//
// Why the polygon's vertices, up to 8: a penalty law sums per-point forces,
// so the points must span the patch for the force and torque to be right.
// Two convex quadrilaterals intersect in at most 8 vertices (a square turned
// 45 degrees on another: the octagon), and the reference plane's cut keeps
// at most 8 of them below it. Why weights: they sum to 4 on every patch
// (the statics of a resting box are d = (m g / (4 K))^(1/n) on a rectangle
// and on the octagon alike), and a vertex made by a clip takes its share
// of the turn of the vertex it split from, so that the patch's elastic
// energy is continuous in the poses (no point appears or leaves deep).
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

// Vertices of a patch's polygon closer than this fraction of the smaller
// box's smallest half size are one point (the deeper): clipping a corner that
// sits on a side plane (two equal boxes face to face) yields it twice up to
// round-off (~1e-16 of the size). Far below the patches of the shallowest
// contacts (a corner 1e-7 of the size in, tilted, spans ~1e-7), whose shape
// gives the weights; merging two vertices sums their turns, so the weights
// barely move (patch.h, PatchBelow). Two faces turned by e rad keep the
// octagon's 8 vertices however small e is: their weights, not their count,
// give the patch its force.
inline constexpr double kBoxPointMergeFraction = 1e-9;

// What decided the contact.
enum class BoxFeature {
  kNone,       // apart by more than the margin
  kFaceOfA,    // a face of box a is the reference face
  kFaceOfB,    // a face of box b is the reference face
  kEdgeEdge,   // an edge of each box
};

struct BoxPoint {
  Vector3 pos{};     // midway between the surfaces, world frame (m)
  double depth = 0;  // along the contact's normal, > 0 overlapping (m)
  // the point's share of the contact's force: the law's force at depth
  // times weight (a face patch's points: geometry/patch.h, PatchBelow; an
  // edge contact's one point: 1)
  double weight = 1;
  // How depth changes with a displacement x of b relative to a at pos:
  // -gradient . x (world frame; its component along the contact's normal is
  // 1). The force whose work the elastic energy weight * U(depth) stores
  // pushes b along gradient with the law's force times weight. An incident
  // corner and an edge contact's point: the contact's normal. A face patch's
  // point that slides along an incident edge or lies on the reference face's
  // corner: turned from it, and longer (geometry/patch.h, ClipVertex).
  Vector3 gradient{};
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
