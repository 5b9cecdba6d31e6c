// Copyright contactlaws authors.
//
// LongestFirst, the plan of a cluster job's items over its processes: the
// longest first onto the least loaded, ties to the lowest process, within
// Graham's 4/3 of the best balance.

#include "ident/work_spread.h"

#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace contactlaws {
namespace {

TEST(WorkSpreadTest, TheLongestGoFirstAndTiesToTheLowestProcess) {
  // 3 and 3 to processes 0 and 1; a 2 to 0 (tied at 3); a 2 to 1 (3 < 5);
  // the last 2 to 0 (tied at 5)
  EXPECT_EQ(LongestFirst({3, 3, 2, 2, 2}, 2), (std::vector<int>{0, 1, 0, 1, 0}));
  // equal costs keep their order, dealt in turn
  EXPECT_EQ(LongestFirst({1, 1, 1, 1}, 3), (std::vector<int>{0, 1, 2, 0}));
  EXPECT_TRUE(LongestFirst({}, 4).empty());
}

TEST(WorkSpreadTest, TheLoadIsWithinGrahamsBound) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> cost(0.1, 1.0);
  for (int processes : {2, 3, 8}) {
    std::vector<double> seconds(50);
    for (double& s : seconds) s = cost(random);
    const std::vector<int> owner = LongestFirst(seconds, processes);
    std::vector<double> load(processes, 0.0);
    double total = 0, longest = 0;
    for (size_t k = 0; k < seconds.size(); ++k) {
      load[owner[k]] += seconds[k];
      total += seconds[k];
      longest = std::max(longest, seconds[k]);
    }
    // the best makespan is at least the mean load and the longest item
    const double best_bound = std::max(total / processes, longest);
    EXPECT_LE(*std::max_element(load.begin(), load.end()), 4.0 / 3.0 * best_bound);
  }
}

}  // namespace
}  // namespace contactlaws
