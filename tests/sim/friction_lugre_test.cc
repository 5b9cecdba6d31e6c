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

#include "contactlaws/advance.h"
#include "mujoco_test_util.h"
#include "sim/friction_scenes.h"

namespace contactlaws {
namespace {

using testing::FrictionScene;
using testing::kG;
using testing::kRadius;
using testing::Vx;
using testing::X;

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
  constexpr double kMu = 0.4;
  constexpr double kV0 = 1.0;
  Simulation& sim =
      MakeSimulation(FrictionScene(false, 0, kG, "1 0 0 0 0 0", "friction=lugre mu=0.4"));
  mj_forward(sim.model(), sim.data());
  const double start = sim.Energy().total();
  RunUntil(sim, 0.5);
  ASSERT_FALSE(sim.contacts().divergence());
  const double distance = kV0 * kV0 / (2 * kMu * kG);
  // as coulomb's block (friction_test): the corners' springs rock a little
  // under the friction's moment; LuGre adds its presliding, mu / sigma0 =
  // 4 um. Measured: 4.1e-4 (fixed) and 6.9e-4 (auto) of the distance.
  constexpr double kDistanceTolerance = 5e-3;  // relative
  EXPECT_NEAR(X(sim), distance, kDistanceTolerance * distance);
  constexpr double kRestSpeed = 1e-4;  // m/s, as coulomb's
  EXPECT_NEAR(Vx(sim), 0, kRestSpeed);
  mj_forward(sim.model(), sim.data());
  const EnergyLedger e = sim.Energy();
  // the kinetic energy went to friction (and a little to the normal law's
  // damping), the total kept: as coulomb's. Measured: the total gains 3.9e-4
  // (fixed) and 7.1e-4 (auto) of 1/2 m v0^2, the bristles' quick settling
  // at the start missed by the trapezoid of friction's power (the thrown
  // box of friction_energy_test).
  constexpr double kLedgerTolerance = 1e-2;  // relative to 1/2 m v0^2
  EXPECT_NEAR(e.dissipated, 0.5 * kV0 * kV0, kLedgerTolerance * 0.5);
  EXPECT_NEAR(e.total(), start, kLedgerTolerance * 0.5);
  std::printf("lugre block: x %.7f of %.7f, dissipated %.6f, total %.6f -> %.6f\n", X(sim),
              distance, e.dissipated, start, e.total());
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
  const Impact& impact = sim.contacts().impacts()[0];
  const double e = impact.restitution_post();
  const double vn = impact.impact_velocity;
  // the lever R - d/2 of coulomb's test (2.5e-2); the bristles act from the
  // touch, and no damper push: measured 1.7e-2, as coulomb's
  constexpr double kImpulseTolerance = 2.5e-2;  // relative
  const double vt = 2 - kMu * (1 + e) * vn;
  EXPECT_NEAR(Vx(sim), vt, kImpulseTolerance * (2 - vt));
  const double spin = 2.5 * kMu * (1 + e) * vn;
  EXPECT_NEAR(sim.data()->qvel[4] * kRadius, spin, kImpulseTolerance * spin);
  std::printf("lugre oblique: e %.4f, vt' %.5f (%.5f), wR %.5f (%.5f)\n", e, Vx(sim), vt,
              sim.data()->qvel[4] * kRadius, spin);
}

INSTANTIATE_TEST_SUITE_P(Steppings, LuGreTest, ::testing::Values(Stepping::kFixed, Stepping::kAuto),
                         Name);

}  // namespace
}  // namespace contactlaws
