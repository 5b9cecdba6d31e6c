// Copyright contactlaws authors.
//
// What the tags need to know of an mjModel: its <text> entries, and the
// properties of geoms and geom pairs (no simulation state).

#ifndef CONTACTLAWS_SCENE_MODEL_QUERIES_H_
#define CONTACTLAWS_SCENE_MODEL_QUERIES_H_

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
