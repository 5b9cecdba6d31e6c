// Copyright contactlaws authors.
//
// Stacks of two and three tagged cubes on a tagged floor stand 10 s: no
// divergence, the top cube within 1e-4 m sideways, no energy gained, and the
// rest depths of the statics. Box-box contacts come from contactlaws' own
// kernel (mujoco/narrowphase.h); the floor-cube contact is MuJoCo's plane-box
// (exact, 4 corners).
//
// Statics: an interface carrying the weight W of the cubes above it at one
// depth (a centred stack) rests at d = (W / (4 K))^(1/n): the plane-box's 4
// corners, and box-box's face patch, whose points' weights sum to 4 (4
// corners of weight 1, or the octagon's 8 of weight 1/2). A
// stack offset along x loads each interface off its centre: the patch is the
// rectangle of two rows of points, x = c -+ hw, and the moments give each row
// F = W/2 (1 -+ e/hw) (e: the load's offset from c), each of its two points
// at d = (F / (2 K))^(1/n).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

constexpr double kHalf = 0.05;        // cube half size, m
constexpr double kMass = 1.0;         // kg per cube
constexpr double kGravity = 9.81;     // m/s^2
constexpr double kStiffness = 1e7;    // K, N/m^1.5
constexpr double kExponent = 1.5;
// The floor of v0. The cubes start exactly touching, so every episode starts
// at the floor; at the default 1e-3 m/s the damping K d^n a d'/v0 of the
// settling (d' ~ 1e-2 m/s) is so stiff that RK4 at 1e-4 s locks the three-cube
// stack into a fixed point with the velocities nonzero (measured: the state
// frozen, the lower interface at zero force, the ledger rising 0.04 J/s).
constexpr double kMinImpactVelocity = 1e-2;  // m/s
constexpr double kTimestep = 1e-4;    // s, RK4: ~60 steps per period of the stiffest mode
constexpr double kDuration = 10.0;    // s

// The top cube may move this far sideways in 10 s (issue 11).
constexpr double kSidewaysTolerance = 1e-4;  // m
// No energy gained: the ledger's total may rise by RK4's error at 1e-4 s,
// this fraction of the stack's potential energy scale m g h (measured below
// 1e-9; the laws only dissipate).
constexpr double kEnergyGainTolerance = 1e-7;
// Rest depths after 10 s against the statics: what is left of the settling
// oscillation, damped by Hunt-Crossley at e = 0.5.
constexpr double kRestDepthTolerance = 1e-3;  // relative

struct Stack {
  const char* name;
  const char* id;  // the test's name
  int cubes;
  double offset;  // x offset of each cube on the one below, m
  double turn;    // turn of each cube about the vertical on the one below, degrees
};

// gtest prints the stack by its name.
void PrintTo(const Stack& s, std::ostream* os) { *os << s.name; }

std::string StackXml(const Stack& s) {
  std::string bodies, tags;
  for (int i = 0; i < s.cubes; ++i) {
    bodies += fmt::format(
        R"(<body name="c{0}" pos="{1} 0 {2}" euler="0 0 {3}"><freejoint/>
             <geom name="c{0}" type="box" size="{4} {4} {4}" mass="{5}"/></body>
)",
        i, i * s.offset, kHalf * (2 * i + 1), i * s.turn, kHalf, kMass);
    tags += fmt::format(
        R"(<text name="contactlaw:t{0}" data="geom1={1} geom2=c{0} law=hunt-crossley restitution=0.5 stiffness={2} exponent={3} min_impact_velocity={4} friction=none"/>
)",
        i, i == 0 ? std::string("floor") : fmt::format("c{}", i - 1), kStiffness, kExponent,
        kMinImpactVelocity);
  }
  return fmt::format(R"(
<mujoco>
  <option timestep="{}" integrator="RK4" gravity="0 0 -{}"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    {}
  </worldbody>
  <custom>{}</custom>
</mujoco>)",
                     kTimestep, kGravity, bodies, tags);
}

// The depth of each point of interface t (below cube t) by the statics, in
// the order of their x (two rows of points for an offset stack).
double RestDepth(double force_per_point) {
  return std::pow(force_per_point / kStiffness, 1 / kExponent);
}

struct Outcome {
  double sideways = 0;     // largest sideways move of the top cube, m
  double energy_gain = 0;  // largest rise of the ledger's total, J
  double seconds = 0;      // wall time of the run
  bool complete = false;
};

class BoxStackTest : public testing::MujocoTest {
 protected:
  // Advances sim to time `until`, following the top cube and the ledger from
  // the first call on.
  Outcome Run(Simulation& sim, const Stack& s, double until) {
    const int top = s.cubes - 1;
    if (!started_) {
      x0_ = sim.data()->qpos[7 * top];
      y0_ = sim.data()->qpos[7 * top + 1];
      sim.Sample(&row_);
      total0_ = sim.Energy().total();
      started_ = true;
    }
    AdvanceOptions options;
    options.duration = until;
    options.sample_rate = 100;
    const auto begin = std::chrono::steady_clock::now();
    const AdvanceResult result = Advance(&sim, options, [&](const std::vector<double>&) {
      const mjtNum* q = sim.data()->qpos + 7 * top;
      outcome_.sideways = std::max(outcome_.sideways, std::hypot(q[0] - x0_, q[1] - y0_));
      outcome_.energy_gain = std::max(outcome_.energy_gain, sim.Energy().total() - total0_);
    });
    outcome_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    outcome_.complete = result.status == AdvanceResult::Status::kComplete;
    return outcome_;
  }

  // The worst relative error of the depths of interface t's points (ordered
  // by x) against the statics.
  double RestDepthError(const Simulation& sim, int t, const std::vector<double>& expected) {
    std::vector<std::pair<double, double>> points;  // x, depth
    for (const PointEvaluation& e : sim.contacts().latest()) {
      if (e.tag == t) points.push_back({e.pos[0], e.depth});
    }
    std::sort(points.begin(), points.end());
    EXPECT_EQ(points.size(), expected.size()) << "interface " << t;
    if (points.size() != expected.size()) return 1;
    double worst = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      worst = std::max(worst, std::fabs(points[i].second / expected[i] - 1));
    }
    return worst;
  }

  double StaticsError(const Simulation& sim, const Stack& s) {
    double worst = 0;
    for (int t = 0; t < s.cubes; ++t) {
      worst = std::max(worst, RestDepthError(sim, t, s.offset > 0 ? OffsetDepths(s, t)
                                                                   : CentredDepths(s, t)));
    }
    return worst;
  }

  static std::vector<double> CentredDepths(const Stack& s, int t);
  static std::vector<double> OffsetDepths(const Stack& s, int t);

 private:
  std::vector<double> row_;
  bool started_ = false;
  double x0_ = 0, y0_ = 0, total0_ = 0;
  Outcome outcome_;
};

// The statics of a centred stack: interface t carries the cubes from t up on
// 4 points, 8 between cubes turned 45 degrees (the octagon), of weights
// summing to 4.
std::vector<double> BoxStackTest::CentredDepths(const Stack& s, int t) {
  const int points = t > 0 && s.turn == 45 ? 8 : 4;
  const double weight = (s.cubes - t) * kMass * kGravity;
  return std::vector<double>(points, RestDepth(weight / 4));
}

// The statics of a stack offset along x: two rows of two points.
std::vector<double> BoxStackTest::OffsetDepths(const Stack& s, int t) {
  const double weight = (s.cubes - t) * kMass * kGravity;
  double load = 0;  // the load's x: the mean of the cubes' from t up
  for (int i = t; i < s.cubes; ++i) load += i * s.offset / (s.cubes - t);
  const double centre = t == 0 ? 0 : (t - 0.5) * s.offset;
  const double hw = t == 0 ? kHalf : kHalf - s.offset / 2;
  const double e = load - centre;
  const double low = RestDepth(weight / 4 * (1 - e / hw));
  const double high = RestDepth(weight / 4 * (1 + e / hw));
  return {low, low, high, high};
}

void Report(const Stack& s, const Outcome& o, double depth_error) {
  std::printf("%-16s sideways %.3g m, energy gain %.3g J, rest depth error %.3g, wall %.2f s\n",
              s.name, o.sideways, o.energy_gain, depth_error, o.seconds);
}

// One run per stack (ctest runs them side by side).
class CentredStack : public BoxStackTest, public ::testing::WithParamInterface<Stack> {};

TEST_P(CentredStack, StandsTenSeconds) {
  const Stack& s = GetParam();
  Simulation& sim = MakeSimulation(StackXml(s));
  const Outcome o = Run(sim, s, kDuration);
  ASSERT_TRUE(o.complete);
  EXPECT_LT(o.sideways, kSidewaysTolerance);
  EXPECT_LT(o.energy_gain, kEnergyGainTolerance * s.cubes * kMass * kGravity * kHalf);
  const double error = StaticsError(sim, s);
  EXPECT_LT(error, kRestDepthTolerance);
  Report(s, o, error);
}

INSTANTIATE_TEST_SUITE_P(Stacks, CentredStack,
                         ::testing::Values(Stack{"two aligned", "TwoAligned", 2, 0, 0},
                                           Stack{"three aligned", "ThreeAligned", 3, 0, 0},
                                           Stack{"two turned 45", "TwoTurned45", 2, 0, 45},
                                           Stack{"three turned 45", "ThreeTurned45", 3, 0, 45}),
                         [](const auto& info) { return std::string(info.param.id); });

// Offset stacks settle on the eccentric statics, then slide: the contacts
// have no friction (issue 8), so a normal tilted by the cubes' lean (~2e-4
// rad) pushes the top cube outwards, which leans them more. No frictionless
// stack of compliant cubes loaded off centre has a static equilibrium; this
// test fails the day friction holds them, and then takes the assertions of
// CentredStack.
class OffsetStack : public BoxStackTest, public ::testing::WithParamInterface<Stack> {};

// Settled: the settling oscillation is damped well within this time, the
// slide has not yet begun to matter (measured: 1.6e-5 m at 0.12 s).
constexpr double kSettled = 0.1;  // s

TEST_P(OffsetStack, RestsOnTheStaticsThenSlidesWithoutFriction) {
  const Stack& s = GetParam();
  Simulation& sim = MakeSimulation(StackXml(s));
  const Outcome settled = Run(sim, s, kSettled);
  ASSERT_TRUE(settled.complete);
  EXPECT_LT(settled.sideways, kSidewaysTolerance);
  const double error = StaticsError(sim, s);
  EXPECT_LT(error, kRestDepthTolerance);
  Report(s, settled, error);
  const Outcome o = Run(sim, s, kDuration);
  Report(s, o, error);
  EXPECT_GT(o.sideways, kSidewaysTolerance);
}

INSTANTIATE_TEST_SUITE_P(Stacks, OffsetStack,
                         ::testing::Values(Stack{"two offset", "TwoOffset", 2, 0.015, 0},
                                           Stack{"three offset", "ThreeOffset", 3, 0.015, 0}),
                         [](const auto& info) { return std::string(info.param.id); });

}  // namespace
}  // namespace contactlaws
