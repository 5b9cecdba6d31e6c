// Copyright contactlaws authors.

#include "mujoco/narrowphase.h"

#include <algorithm>
#include <cstring>

#include "geometry/box_box.h"

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

int CollideBoxPair(const mjModel* m, const mjData* d, int g0, int g1, mjtNum margin,
                   mjContact* out) {
  const BoxBoxContact contact = CollideBoxes(BoxOf(m, d, g0), BoxOf(m, d, g1), margin);
  for (int i = 0; i < contact.count; ++i) {
    mjContact& c = out[i];
    std::memset(&c, 0, sizeof(c));
    c.dist = -contact.points[i].depth;
    std::copy(contact.points[i].pos.begin(), contact.points[i].pos.end(), c.pos);
    std::copy(contact.normal.begin(), contact.normal.end(), c.frame);
  }
  return contact.count;
}

}  // namespace

int Collide(const mjModel* m, const mjData* d, int g0, int g1, mjtNum margin, mjContact* out) {
  const int t0 = m->geom_type[g0];
  const int t1 = m->geom_type[g1];
  if (t0 == mjGEOM_BOX && t1 == mjGEOM_BOX) return CollideBoxPair(m, d, g0, g1, margin, out);
  return mjCOLLISIONFUNC[t0][t1](m, d, out, g0, g1, margin);
}

}  // namespace contactlaws
