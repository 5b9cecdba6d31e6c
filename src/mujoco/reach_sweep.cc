// Copyright contactlaws authors.

#include "mujoco/reach_sweep.h"

namespace contactlaws::internal {

ReachSweep::ReachSweep(const mjModel* m) : m_(m), lower_(m->ngeom), upper_(m->ngeom) {
  for (int g = 0; g < m->ngeom; ++g) (m->geom_rbound[g] > 0 ? order_ : unbounded_).push_back(g);
}

void ReachSweep::Sort(const mjData* d, const std::vector<double>& reach) {
  for (const int g : order_) {
    const double r = m_->geom_rbound[g] + reach[g];
    lower_[g] = d->geom_xpos[3 * g] - r;
    upper_[g] = d->geom_xpos[3 * g] + r;
  }
  for (size_t i = 1; i < order_.size(); ++i) {
    const int g = order_[i];
    size_t j = i;
    for (; j > 0 && lower_[order_[j - 1]] > lower_[g]; --j) order_[j] = order_[j - 1];
    order_[j] = g;
  }
}

}  // namespace contactlaws::internal
