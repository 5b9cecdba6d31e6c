// Copyright contactlaws authors.
//
// ReachSweep: the geom pairs whose bounding spheres, each grown by a reach of
// its own, overlap: a sweep along x over the geoms sorted by their lower
// bound (kept from one call to the next, so that the sort of a scene that
// moves little is one pass). A rule over the pairs apart then costs the pairs
// near each other, not every pair: 216 balls have 23,436 tagged pairs and a
// few hundred neighbours. Geoms without a bounding sphere (planes, height
// fields: rbound 0) overlap every geom.

#ifndef CONTACTLAWS_MUJOCO_REACH_SWEEP_H_
#define CONTACTLAWS_MUJOCO_REACH_SWEEP_H_

#include <cmath>
#include <vector>

#include <mujoco/mujoco.h>

namespace contactlaws::internal {

class ReachSweep {
 public:
  explicit ReachSweep(const mjModel* m);

  // Calls visit(g0, g1) once for every geom pair whose bounding spheres at
  // d's geom_xpos, radii rbound + reach[g] (m, >= 0, inf: everything),
  // overlap, and for every pair with a geom without a bounding sphere.
  template <class Visit>
  void Overlaps(const mjData* d, const std::vector<double>& reach, Visit visit);

 private:
  // Sorts order_ by the lower x bounds (insertion sort: nearly sorted).
  void Sort(const mjData* d, const std::vector<double>& reach);

  const mjModel* m_;
  std::vector<int> order_;      // geoms with a bounding sphere
  std::vector<int> unbounded_;  // geoms without one
  std::vector<double> lower_;   // per geom: its sphere's lowest x, m
  std::vector<double> upper_;   // per geom: its sphere's highest x, m
};

template <class Visit>
void ReachSweep::Overlaps(const mjData* d, const std::vector<double>& reach, Visit visit) {
  const int n = static_cast<int>(order_.size());
  for (size_t i = 0; i < unbounded_.size(); ++i) {
    for (int g = 0; g < m_->ngeom; ++g) {
      // a pair of unbounded geoms once
      if (g != unbounded_[i] && (m_->geom_rbound[g] > 0 || g > unbounded_[i])) {
        visit(unbounded_[i], g);
      }
    }
  }
  Sort(d, reach);
  for (int i = 0; i < n; ++i) {
    const int a = order_[i];
    const double ra = m_->geom_rbound[a] + reach[a];
    for (int j = i + 1; j < n && lower_[order_[j]] <= upper_[a]; ++j) {
      const int b = order_[j];
      const double rb = m_->geom_rbound[b] + reach[b];
      mjtNum between[3];
      mju_sub3(between, d->geom_xpos + 3 * b, d->geom_xpos + 3 * a);
      const double r = ra + rb;
      if (!(mju_dot3(between, between) > r * r)) visit(a, b);
    }
  }
}

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_MUJOCO_REACH_SWEEP_H_
