// Copyright contactlaws authors.
//
// What a frame is about: the bodies that move (a tree of bodies hanging off
// the world with at least one degree of freedom; a driven mocap body has
// none), where their geoms are, and how large and heavy each tree is. The
// tracking camera frames their box; the force arrows are scaled to them.

#ifndef CONTACTLAWS_RENDER_MOVING_BODIES_H_
#define CONTACTLAWS_RENDER_MOVING_BODIES_H_

#include <vector>

#include <mujoco/mujoco.h>

namespace contactlaws::render {

// An axis-aligned box in the world frame, m; empty until something is added.
struct Box {
  double lo[3] = {mjMAXVAL, mjMAXVAL, mjMAXVAL};
  double hi[3] = {-mjMAXVAL, -mjMAXVAL, -mjMAXVAL};

  bool empty() const { return lo[0] > hi[0]; }
  // the box around a sphere
  void Add(const double centre[3], double radius);
  void Add(const Box& box);
  double LargestSide() const;  // 0 when empty
};

class MovingBodies {
 public:
  // d: a state after mj_kinematics (Simulation::Sample's), where the sizes
  // are measured.
  MovingBodies(const mjModel* m, const mjData* d);

  bool empty() const { return geoms_.empty(); }
  // The box of the moving geoms' bounding spheres (geom_rbound, so that it
  // does not change as a body turns) in d; planes have none.
  Box Extent(const mjData* d) const;
  // Whether body b moves.
  bool Moves(int body) const { return tree_[body] >= 0; }
  // The largest side of the box of body's tree at the measured state, m;
  // 0 for a body that does not move.
  double Size(int body) const;
  // Arrow length per newton on body's tree, m/N: the tree's weight (its
  // mass times |g|, or standard gravity when the scene has none) is drawn as
  // long as the tree's size; 0 for a body that does not move.
  double ArrowScale(int body) const;

 private:
  const mjModel* m_;
  std::vector<int> geoms_;   // of moving bodies, planes left out
  std::vector<int> tree_;    // per body: its root body (a child of the world), -1: static
  std::vector<double> size_;   // per root body, m
  std::vector<double> scale_;  // per root body, m/N
};

}  // namespace contactlaws::render

#endif  // CONTACTLAWS_RENDER_MOVING_BODIES_H_
