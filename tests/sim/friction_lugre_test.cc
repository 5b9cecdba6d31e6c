// Copyright contactlaws authors.
//
// LuGre inside MuJoCo against the closed forms the other models meet: a
// block launched along a floor stops after v0^2 / (2 mu g), and a ball in an
// oblique impact in gross sliding leaves by the impulse law. Each at the
// scenes' fixed step and under --timestep auto. A slide starts with the
// bristles at rest (z = 0) at 1 m/s: a bristle damper that did not fade with
// the slip speed pushed sigma1 v for a whole step there, and threw the block.

#include <cmath>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "contactlaws/simulation.h"
#include "mujoco_test_util.h"
#include "sim/friction_scenes.h"

namespace contactlaws {
namespace {

using testing::FrictionScene;
using testing::kG;

// How the test steps: the scene's fixed step, or the auto timestep.
enum class Stepping { kFixed, kAuto };

void PrintTo(Stepping s, std::ostream* os) { *os << (s == Stepping::kFixed ? "fixed" : "auto"); }

std::string Name(const ::testing::TestParamInfo<Stepping>& info) {
  return info.param == Stepping::kFixed ? "Fixed" : "Auto";
}

class LuGreTest : public testing::MujocoTest, public ::testing::WithParamInterface<Stepping> {
 protected:
  // Advances sim to time t, as GetParam() says.
  void RunUntil(Simulation& sim, double t) {
    if (GetParam() == Stepping::kFixed) {
      testing::RunUntil(sim, t);
      return;
    }
    AdvanceOptions options;
    options.duration = t;
    options.auto_timestep = AutoTimestepOptions{};
    const AdvanceResult result = Advance(&sim, options, [](const std::vector<double>&) {});
    ASSERT_EQ(result.status, AdvanceResult::Status::kComplete);
  }
};

TEST_P(LuGreTest, BlockStopsAfterTheKineticDistanceAndDissipatesItsEnergy) {
  Simulation& sim =
      MakeSimulation(FrictionScene(false, 0, kG, "1 0 0 0 0 0", "friction=lugre mu=0.4"));
  mj_forward(sim.model(), sim.data());
  const double start = sim.Energy().total();
  RunUntil(sim, 0.5);
  ASSERT_FALSE(sim.contacts().divergence());
  testing::ExpectKineticStop(sim, /*mu=*/0.4, /*v0=*/1.0, start, "lugre block");
}

TEST_P(LuGreTest, ObliqueImpactInGrossSlidingMatchesTheImpulseLaw) {
  // as coulomb's (friction_test): gravity off, 1 m/s down and 2 m/s along x,
  // no spin; gross sliding since 2 > 7/2 mu (1 + e) v_n
  constexpr double kMu = 0.2;
  std::string scene = testing::ObliqueImpact(2, kMu);
  scene.replace(scene.find("mu="), 3, "friction=lugre mu=");
  Simulation& sim = MakeSimulation(scene);
  while (sim.contacts().impacts().empty() || sim.contacts().impacts()[0].open) {
    RunUntil(sim, sim.time() + 1e-4);
  }
  testing::ExpectImpulseLaw(sim, sim.contacts().impacts()[0], kMu, 2, "lugre oblique");
}

INSTANTIATE_TEST_SUITE_P(Steppings, LuGreTest, ::testing::Values(Stepping::kFixed, Stepping::kAuto),
                         Name);

}  // namespace
}  // namespace contactlaws
