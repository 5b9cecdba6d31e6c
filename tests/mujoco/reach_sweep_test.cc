// Copyright contactlaws authors.
//
// ReachSweep: the pairs it visits are exactly those whose grown bounding
// spheres overlap (brute force over every pair), each once, plus every pair
// with a plane, as the geoms move and the reaches change.

#include "mujoco/reach_sweep.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contactlaws/contactlaws.h"

namespace contactlaws::internal {
namespace {

TEST(ReachSweepTest, VisitsExactlyThePairsWhoseGrownSpheresOverlap) {
  constexpr int kBalls = 40;
  std::string xml = "<mujoco><worldbody><geom name=\"floor\" type=\"plane\" size=\"5 5 0.1\"/>"
                    "<geom name=\"wall\" type=\"plane\" zaxis=\"1 0 0\" size=\"5 5 0.1\"/>";
  std::mt19937 random(22);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < kBalls; ++i) {
    xml += fmt::format("<body pos=\"{} {} {}\"><freejoint/><geom type=\"sphere\" size=\"{}\"/></body>",
                       2 * unit(random), 2 * unit(random), 2 * unit(random),
                       0.05 + 0.1 * unit(random));
  }
  xml += "</worldbody></mujoco>";
  const UniqueModel model = LoadModelString(xml, "sweep.xml");
  const mjModel* m = model.get();
  UniqueData data(mj_makeData(m));
  mjData* d = data.get();
  ReachSweep sweep(m);
  std::vector<double> reach(m->ngeom);
  for (int round = 0; round < 20; ++round) {
    // the balls move a little (the order the sweep keeps goes stale) and
    // the reaches change; the last round reaches everything
    for (int i = 0; i < kBalls; ++i) {
      for (int k = 0; k < 3; ++k) d->qpos[7 * i + k] += 0.2 * (unit(random) - 0.5);
    }
    mj_kinematics(m, d);
    for (double& r : reach) r = round == 19 ? INFINITY : 0.3 * unit(random);
    std::set<std::pair<int, int>> visited;
    sweep.Overlaps(d, reach, [&](int a, int b) {
      EXPECT_TRUE(visited.emplace(std::min(a, b), std::max(a, b)).second)
          << "visited twice: " << a << ", " << b;
    });
    std::set<std::pair<int, int>> expected;
    for (int a = 0; a < m->ngeom; ++a) {
      for (int b = a + 1; b < m->ngeom; ++b) {
        const bool bounded = m->geom_rbound[a] > 0 && m->geom_rbound[b] > 0;
        mjtNum between[3];
        mju_sub3(between, d->geom_xpos + 3 * b, d->geom_xpos + 3 * a);
        const double r = m->geom_rbound[a] + reach[a] + m->geom_rbound[b] + reach[b];
        if (!bounded || mju_norm3(between) <= r) expected.emplace(a, b);
      }
    }
    EXPECT_EQ(visited, expected) << "round " << round;
    // the test means something: some pairs in, most out (but the last round)
    if (round < 19) {
      EXPECT_LT(expected.size(), static_cast<size_t>(m->ngeom * (m->ngeom - 1) / 4));
    }
  }
}

}  // namespace
}  // namespace contactlaws::internal
