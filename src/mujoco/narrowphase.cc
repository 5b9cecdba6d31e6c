// Copyright contactlaws authors.

#include "mujoco/narrowphase.h"

#include <algorithm>
#include <cstring>

#include "geometry/box_box.h"
#include "geometry/polytope.h"
#include "scene/model_queries.h"

namespace contactlaws {
namespace {

// Geom g as the box kernel sees it: its frame and half sizes.
OrientedBox BoxOf(const mjModel* m, const mjData* d, int g) {
  OrientedBox box;
  std::copy(d->geom_xpos + 3 * g, d->geom_xpos + 3 * g + 3, box.centre.begin());
  std::copy(d->geom_xmat + 9 * g, d->geom_xmat + 9 * g + 9, box.rotation.begin());
  std::copy(m->geom_size + 3 * g, m->geom_size + 3 * g + 3, box.half.begin());
  return box;
}

// Mesh geom g (IsPolytope) as the polytope kernel sees it: its hull's
// vertices in the world frame and its hull's triangles. MuJoCo 2.2.2's hull
// graph (user_mesh.cc, MakeGraph): numvert, numface, vert_edgeadr[numvert],
// vert_globalid[numvert], edge_localid[numvert + 3 numface],
// face_globalid[3 numface], the faces' vertices as indices into the mesh's
// vertices (mesh_vert: floats in the geom's frame).
void MeshPolytope(const mjModel* m, const mjData* d, int g, Polytope* p) {
  const int mesh = m->geom_dataid[g];
  const int* graph = m->mesh_graph + m->mesh_graphadr[mesh];
  const int numvert = graph[0], numface = graph[1];
  const int* globalid = graph + 2 + numvert;
  const int* faces = graph + 2 + 3 * numvert + 3 * numface;
  const float* vert = m->mesh_vert + 3 * m->mesh_vertadr[mesh];
  const mjtNum* pos = d->geom_xpos + 3 * g;
  const mjtNum* mat = d->geom_xmat + 9 * g;
  p->vertex_count = numvert;
  for (int i = 0; i < numvert; ++i) {
    const float* v = vert + 3 * globalid[i];
    for (int r = 0; r < 3; ++r) {
      const mjtNum* row = mat + 3 * r;
      p->vertices[i][r] = pos[r] + row[0] * v[0] + row[1] * v[1] + row[2] * v[2];
    }
  }
  p->triangle_count = numface;
  for (int f = 0; f < numface; ++f) {
    for (int k = 0; k < 3; ++k) {
      // the hull vertex whose global id the face names
      const int* local = std::find(globalid, globalid + numvert, faces[3 * f + k]);
      p->triangles[f][k] = static_cast<int>(local - globalid);
    }
  }
}

void PolytopeOf(const mjModel* m, const mjData* d, int g, Polytope* p) {
  if (m->geom_type[g] == mjGEOM_BOX) {
    *p = PolytopeOfBox(BoxOf(m, d, g));
  } else {
    MeshPolytope(m, d, g, p);
  }
}

// The contact's points as MuJoCo's: dist, pos, frame[0..2] the normal;
// their weights and depth gradients in weight and gradient (when given).
template <typename Contact>
int Write(const Contact& contact, mjContact* out, double* weight, mjtNum* gradient) {
  for (int i = 0; i < contact.count; ++i) {
    const BoxPoint& point = contact.points[i];
    if (weight) weight[i] = point.weight;
    if (gradient) std::copy(point.gradient.begin(), point.gradient.end(), gradient + 3 * i);
    mjContact& c = out[i];
    std::memset(&c, 0, sizeof(c));
    c.dist = -point.depth;
    std::copy(point.pos.begin(), point.pos.end(), c.pos);
    std::copy(contact.normal.begin(), contact.normal.end(), c.frame);
  }
  return contact.count;
}

// Two polytopes, or -1 when the kernel declines (degenerate hull).
int CollidePolytopePair(const mjModel* m, const mjData* d, int g0, int g1, mjtNum margin,
                        mjContact* out, double* weight, mjtNum* gradient) {
  Polytope a, b;
  PolytopeOf(m, d, g0, &a);
  PolytopeOf(m, d, g1, &b);
  const PolytopeContact contact = CollidePolytopes(a, b, margin);
  if (contact.feature == PolytopeFeature::kUnsupported) return -1;
  return Write(contact, out, weight, gradient);
}

}  // namespace

int Collide(const mjModel* m, const mjData* d, int g0, int g1, mjtNum margin, mjContact* out,
            double* weight, mjtNum* gradient) {
  switch (NarrowphaseOf(m, g0, g1)) {
    case Narrowphase::kBoxBox:
      return Write(CollideBoxes(BoxOf(m, d, g0), BoxOf(m, d, g1), margin), out, weight, gradient);
    case Narrowphase::kPolytope:
      if (const int count = CollidePolytopePair(m, d, g0, g1, margin, out, weight, gradient);
          count >= 0) {
        return count;
      }
      break;
    default: break;
  }
  const int count = mjCOLLISIONFUNC[m->geom_type[g0]][m->geom_type[g1]](m, d, out, g0, g1, margin);
  if (weight) std::fill(weight, weight + count, 1.0);
  for (int i = 0; gradient && i < count; ++i) std::copy(out[i].frame, out[i].frame + 3, gradient + 3 * i);
  return count;
}

}  // namespace contactlaws
