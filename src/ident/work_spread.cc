// Copyright contactlaws authors.

#include "ident/work_spread.h"

#include <algorithm>
#include <numeric>

namespace contactlaws::internal {

std::vector<int> LongestFirst(const std::vector<double>& seconds, int processes) {
  std::vector<int> order(seconds.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return seconds[a] > seconds[b]; });
  std::vector<double> load(processes, 0.0);
  std::vector<int> owner(seconds.size());
  for (const int k : order) {
    const int r = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    owner[k] = r;
    load[r] += seconds[k];
  }
  return owner;
}

}  // namespace contactlaws::internal
