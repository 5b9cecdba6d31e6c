// Copyright contactlaws authors.

#include "scene/model_queries.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "contactlaws/contact_model.h"
#include "geometry/box_box.h"
#include "geometry/polytope.h"

namespace contactlaws {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

std::string_view TextName(const mjModel* m, int i) {
  return m->names + m->name_textadr[i];
}

std::string_view TextData(const mjModel* m, int i) {
  const char* data = m->text_data + m->text_adr[i];
  return std::string_view(data, strnlen(data, m->text_size[i]));
}

bool IsPolytope(const mjModel* m, int g) {
  if (m->geom_type[g] == mjGEOM_BOX) return true;
  if (m->geom_type[g] != mjGEOM_MESH) return false;
  const int mesh = m->geom_dataid[g];
  const int graph = mesh < 0 ? -1 : m->mesh_graphadr[mesh];
  if (graph < 0) return false;  // no hull: fewer than 4 vertices, or qhull failed
  // the graph's head (user_mesh.cc, MakeGraph): numvert, numface
  return m->mesh_graph[graph] <= kMaxPolytopeVertices &&
         m->mesh_graph[graph + 1] <= kMaxPolytopeTriangles;
}

std::array<int, 2> CollisionOrder(const mjModel* m, int g1, int g2) {
  return m->geom_type[g1] > m->geom_type[g2] ? std::array<int, 2>{g2, g1}
                                             : std::array<int, 2>{g1, g2};
}

int MaxContacts(const mjModel* m, int g1, int g2) {
  const int type1 = m->geom_type[g1];
  const int type2 = m->geom_type[g2];
  auto either = [&](int type) { return type1 == type || type2 == type; };
  if (either(mjGEOM_SPHERE) || either(mjGEOM_ELLIPSOID)) return 1;
  // box-box, box-mesh, mesh-mesh are contactlaws' own: the patch's vertices
  switch (NarrowphaseOf(m, g1, g2)) {
    case Narrowphase::kBoxBox: return kMaxBoxBoxPoints;
    case Narrowphase::kPolytope: return kMaxPolytopePoints;
    default: break;
  }
  // mjc_Convex (engine_collision_convex.c): one point, or more with multiCCD
  const bool convex = (either(mjGEOM_CYLINDER) || either(mjGEOM_MESH)) &&
                      !either(mjGEOM_PLANE) && !either(mjGEOM_HFIELD);
  if (convex && !(m->opt.enableflags & mjENBL_MULTICCD)) return 1;
  return mjMAXCONPAIR;
}

std::optional<double> HertzRadius(const mjModel* m, int g) {
  switch (m->geom_type[g]) {
    case mjGEOM_PLANE: return kInfinity;
    case mjGEOM_SPHERE:
    case mjGEOM_CAPSULE: return m->geom_size[3 * g];
    default: return std::nullopt;
  }
}

bool IsExcluded(const mjModel* m, int b1, int b2) {
  const int s1 = ((b1 + 1) << 16) + b2 + 1;
  const int s2 = ((b2 + 1) << 16) + b1 + 1;
  for (int i = 0; i < m->nexclude; ++i) {
    if (m->exclude_signature[i] == s1 || m->exclude_signature[i] == s2) {
      return true;
    }
  }
  return false;
}

bool IsExplicitPair(const mjModel* m, int g1, int g2) {
  for (int i = 0; i < m->npair; ++i) {
    if ((m->pair_geom1[i] == g1 && m->pair_geom2[i] == g2) ||
        (m->pair_geom1[i] == g2 && m->pair_geom2[i] == g1)) {
      return true;
    }
  }
  return false;
}

double GeomSize(const mjModel* m, int g) {
  const mjtNum* size = m->geom_size + 3 * g;
  switch (m->geom_type[g]) {
    case mjGEOM_PLANE:
    case mjGEOM_HFIELD: return kInfinity;
    case mjGEOM_SPHERE:
    case mjGEOM_CAPSULE: return size[0];
    case mjGEOM_CYLINDER: return std::min(size[0], size[1]);
    case mjGEOM_ELLIPSOID:
    case mjGEOM_BOX: return std::min({size[0], size[1], size[2]});
    default: return m->geom_rbound[g];
  }
}

}  // namespace contactlaws
