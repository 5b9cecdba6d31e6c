// Copyright contactlaws authors.
//
// What the tags need to know of an mjModel: its <text> entries, and the
// properties of geoms and geom pairs (no simulation state).

#ifndef CONTACTLAWS_SCENE_MODEL_QUERIES_H_
#define CONTACTLAWS_SCENE_MODEL_QUERIES_H_

#include <algorithm>
#include <array>
#include <optional>
#include <string_view>

#include <mujoco/mujoco.h>

namespace contactlaws {

// Name and data of <text> entry i.
std::string_view TextName(const mjModel* m, int i);
std::string_view TextData(const mjModel* m, int i);

// Geom g is a polytope contactlaws collides itself (geometry/polytope.h): a
// box, or a mesh whose convex hull (MuJoCo's mesh_graph) is within
// kMaxPolytopeVertices and kMaxPolytopeTriangles.
bool IsPolytope(const mjModel* m, int g);

// The narrowphase that collides geoms g1 and g2 of m (mujoco/narrowphase.h),
// in either order: contactlaws' box-box (geometry/box_box.h), its polytopes
// (a box or polytope mesh with a polytope mesh: geometry/polytope.h; MuJoCo's
// when the kernel declines a degenerate hull), MuJoCo 2.2.2's mjCOLLISIONFUNC
// for every other pair of types it has, or none.
// Inline: the passive hook asks it for every pair near.
enum class Narrowphase { kNone, kBoxBox, kPolytope, kMujoco };
inline Narrowphase NarrowphaseOf(const mjModel* m, int g1, int g2) {
  const int type1 = std::min(m->geom_type[g1], m->geom_type[g2]);
  const int type2 = std::max(m->geom_type[g1], m->geom_type[g2]);
  if (type1 == mjGEOM_BOX && type2 == mjGEOM_BOX) return Narrowphase::kBoxBox;
  if (type2 == mjGEOM_MESH && IsPolytope(m, g1) && IsPolytope(m, g2)) {
    return Narrowphase::kPolytope;
  }
  return mjCOLLISIONFUNC[type1][type2] ? Narrowphase::kMujoco : Narrowphase::kNone;
}

// g1 and g2 in the order mjCOLLISIONFUNC takes them: geom types ascending
// (a plane first).
std::array<int, 2> CollisionOrder(const mjModel* m, int g1, int g2);

// Most contact points the narrowphase (mujoco/narrowphase.h) returns for
// geoms g1 and g2 of m: kMaxPolytopePoints for two polytopes (box-box,
// box-mesh, mesh-mesh: contactlaws' own), one for a sphere or an ellipsoid,
// and for MuJoCo 2.2.2's general convex collider (MPR: a cylinder or a mesh
// beyond the caps with anything but a plane or a height field) unless the
// scene enables multiCCD.
int MaxContacts(const mjModel* m, int g1, int g2);

// Sphere-equivalent radius for the material stiffness (paper eq. 2): a
// sphere's or capsule's radius, infinity for a plane; nullopt otherwise.
std::optional<double> HertzRadius(const mjModel* m, int g);

// Bodies b1 and b2 excluded by <contact><exclude>.
bool IsExcluded(const mjModel* m, int b1, int b2);

// Geoms g1 and g2 named together in a <contact><pair>.
bool IsExplicitPair(const mjModel* m, int g1, int g2);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SCENE_MODEL_QUERIES_H_
