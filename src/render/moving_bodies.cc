// Copyright contactlaws authors.

#include "render/moving_bodies.h"

#include <algorithm>

namespace contactlaws::render {
namespace {

// The weight of a scene without gravity is drawn as under standard gravity.
constexpr double kStandardGravity = 9.80665;  // m/s^2

}  // namespace

void Box::Add(const double centre[3], double radius) {
  for (int i = 0; i < 3; ++i) {
    lo[i] = std::min(lo[i], centre[i] - radius);
    hi[i] = std::max(hi[i], centre[i] + radius);
  }
}

void Box::Add(const Box& box) {
  for (int i = 0; i < 3; ++i) {
    lo[i] = std::min(lo[i], box.lo[i]);
    hi[i] = std::max(hi[i], box.hi[i]);
  }
}

double Box::LargestSide() const {
  if (empty()) return 0;
  return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
}

MovingBodies::MovingBodies(const mjModel* m, const mjData* d)
    : m_(m), tree_(m->nbody, -1), size_(m->nbody, 0), scale_(m->nbody, 0) {
  // a body moves when it is welded to one with joints (body_weldid 0: to
  // the world, as a mocap body is)
  for (int b = 1; b < m->nbody; ++b) {
    if (m->body_weldid[b] > 0) tree_[b] = m->body_rootid[b];
  }
  std::vector<Box> trees(m->nbody);
  for (int g = 0; g < m->ngeom; ++g) {
    const int tree = tree_[m->geom_bodyid[g]];
    if (tree < 0 || m->geom_type[g] == mjGEOM_PLANE) continue;
    geoms_.push_back(g);
    trees[tree].Add(d->geom_xpos + 3 * g, m->geom_rbound[g]);
  }
  double gravity = mju_norm3(m->opt.gravity);
  if (!(gravity > 0)) gravity = kStandardGravity;
  for (int b = 1; b < m->nbody; ++b) {
    const double weight = m->body_subtreemass[b] * gravity;
    size_[b] = trees[b].LargestSide();
    if (weight > 0) scale_[b] = size_[b] / weight;
  }
}

Box MovingBodies::Extent(const mjData* d) const {
  Box box;
  for (int g : geoms_) box.Add(d->geom_xpos + 3 * g, m_->geom_rbound[g]);
  return box;
}

double MovingBodies::Size(int body) const {
  return tree_[body] < 0 ? 0 : size_[tree_[body]];
}

double MovingBodies::ArrowScale(int body) const {
  return tree_[body] < 0 ? 0 : scale_[tree_[body]];
}

}  // namespace contactlaws::render
