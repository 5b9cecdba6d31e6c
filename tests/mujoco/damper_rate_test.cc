// Copyright contactlaws authors.
//
// DamperRate against the rigid-body closed forms: a point at r
// from a free body's centre of mass moves, per unit impulse along t (a
// tangent, or the normal), by 1/m + (r x t) . I^-1 (r x t).

#include "mujoco/damper_rate.h"

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws::internal {
namespace {

class DamperRateTest : public testing::MujocoTest {
 protected:
  // A free body of mass kMass (its geom given) on a static floor, at the
  // state qpos.
  // The four bottom corners of a cube of half size a centred at z = 1 (as
  // Body places it), each with the floor's normal.
  static void BottomCorners(double a, std::vector<mjtNum>* pos, std::vector<mjtNum>* normal) {
    for (const double x : {-a, a}) {
      for (const double y : {-a, a}) {
        pos->insert(pos->end(), {x, y, 1 - a});
        normal->insert(normal->end(), {0, 0, 1});
      }
    }
  }

  mjData* Body(const std::string& geom) {
    model_ = Load(fmt::format(R"(<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="body" pos="0 0 1"><freejoint/><geom {} mass="{}"/></body>
  </worldbody>
</mujoco>)",
                              geom, kMass));
    mjData* d = MakeData(model_.get());
    mj_forward(model_.get(), d);
    pair_.body = {0, 1};
    return d;
  }

  static constexpr double kMass = 0.01;   // kg
  static constexpr double kDamping = 69;  // N s/m per point
  UniqueModel model_;
  GeomPair pair_;
};

TEST_F(DamperRateTest, OnePointUnderABallActsOnItsMassAndItsSpin) {
  // the point R below the centre: 1/m + R^2 / (2/5 m R^2) = 3.5 / m along
  // either tangent
  constexpr double kRadius = 0.1;
  mjData* d = Body(fmt::format(R"(type="sphere" size="{}")", kRadius));
  const mjtNum pos[3] = {0, 0, 1 - kRadius};
  const mjtNum normal[3] = {0, 0, 1};
  DamperRate rate;
  EXPECT_NEAR(rate.Rate(model_.get(), d, pair_, 1, pos, normal, &kDamping),
              kDamping * 3.5 / kMass, 1e-9 * kDamping / kMass);
}

TEST_F(DamperRateTest, FourCornersTurnTheCube12xAndRockIt6xFasterThanOneMovesItsMass) {
  // the bottom corners of a cube of half size a, at r^2 = 2 a^2 from the
  // vertical axis: torsion at 4 c 2 a^2 / I_zz, I_zz = 2/3 m a^2: 12 c / m
  // (the fastest mode; translation with rocking 10 c / m)
  constexpr double kHalf = 0.01;
  mjData* d = Body(fmt::format(R"(type="box" size="{0} {0} {0}")", kHalf));
  std::vector<mjtNum> pos, normal;
  BottomCorners(kHalf, &pos, &normal);
  const std::vector<double> damping(4, kDamping);
  DamperRate rate;
  EXPECT_NEAR(rate.Rate(model_.get(), d, pair_, 4, pos.data(), normal.data(), damping.data()),
              12 * kDamping / kMass, 1e-9 * kDamping / kMass);
  // the normal's own direction is not damped: a normal along x leaves y, z
  const mjtNum side[3] = {1, 0, 0};
  const mjtNum centre[3] = {0, 0, 1};
  EXPECT_NEAR(rate.Rate(model_.get(), d, pair_, 1, centre, side, &kDamping), kDamping / kMass,
              1e-9 * kDamping / kMass);
  // their normal dampers: the cube rises against 4 c on m (4 c / m) and
  // rocks about a horizontal axis against 4 c a^2 on I_xx = 2/3 m a^2
  // (6 c / m), the fastest mode
  EXPECT_NEAR(rate.Rate(model_.get(), d, pair_, 4, pos.data(), normal.data(), damping.data(),
                        DamperDirection::kNormal),
              6 * kDamping / kMass, 1e-9 * kDamping / kMass);
}

TEST_F(DamperRateTest, TheBoundIsTheFrobeniusNormOfTheRatesMatrix) {
  // the cube's four bottom corners and their normal dampers: it rises at
  // 4 c / m and rocks about x and y at 6 c / m, and nothing else moves
  // against them; the bound is sqrt(4^2 + 6^2 + 6^2) c / m, and its margin,
  // 1e-9 of the trace (4 + 6 + 6) c / m
  constexpr double kHalf = 0.01;
  mjData* d = Body(fmt::format(R"(type="box" size="{0} {0} {0}")", kHalf));
  std::vector<mjtNum> pos, normal;
  BottomCorners(kHalf, &pos, &normal);
  const std::vector<double> damping(4, kDamping);
  DamperRate rate;
  const double bound = rate.Bound(model_.get(), d, pair_, 4, pos.data(), normal.data(),
                                  damping.data(), DamperDirection::kNormal);
  EXPECT_NEAR(bound, (std::sqrt(88.0) + 16e-9) * kDamping / kMass, 1e-12 * kDamping / kMass);
  EXPECT_GE(bound, rate.Rate(model_.get(), d, pair_, 4, pos.data(), normal.data(),
                             damping.data(), DamperDirection::kNormal));
  // friction's dampers there, along a tilted normal (a corner on a slope):
  // above the exact rate, within sqrt(6) of it (six dofs: the rank) and the
  // margin
  const std::vector<mjtNum> tilted = {0.6, 0, 0.8, 0.6, 0, 0.8, 0.6, 0, 0.8, 0.6, 0, 0.8};
  const std::vector<mjtNum>* normals[] = {&normal, &tilted};
  for (const std::vector<mjtNum>* n : normals) {
    const double exact =
        rate.Rate(model_.get(), d, pair_, 4, pos.data(), n->data(), damping.data());
    const double tangential = rate.Bound(model_.get(), d, pair_, 4, pos.data(), n->data(),
                                         damping.data(), DamperDirection::kTangential);
    EXPECT_GE(tangential, exact);
    EXPECT_LE(tangential, std::sqrt(6.0) * exact * (1 + 1e-8));
  }
}

TEST_F(DamperRateTest, TwoBallsAmongOthersActOnTheirTwoMassesAlone) {
  // balls 0 and 4 of a row of 6 free balls (their dofs apart, others'
  // between), touching along x: a normal damper between their centres
  // moves both masses, c (1/m + 1/m), and turns neither; the others' dofs
  // take no part
  constexpr double kRadius = 0.1;
  std::string bodies;
  for (int i = 0; i < 6; ++i) {
    // ball 4 touches ball 0; the others stand apart along y
    bodies += fmt::format(R"(<body pos="{} {} 1"><freejoint/><geom type="sphere" size="{}"
      mass="{}"/></body>)", i == 4 ? 2 * kRadius : 0.0, i == 4 ? 0 : i, kRadius, kMass);
  }
  model_ = Load("<mujoco><worldbody>" + bodies + "</worldbody></mujoco>");
  mjData* d = MakeData(model_.get());
  mj_forward(model_.get(), d);
  pair_.body = {1, 5};  // balls 0 and 4: body 0 is the world
  const mjtNum pos[3] = {kRadius, 0, 1};
  const mjtNum normal[3] = {1, 0, 0};
  DamperRate rate;
  EXPECT_NEAR(rate.Rate(model_.get(), d, pair_, 1, pos, normal, &kDamping,
                        DamperDirection::kNormal),
              2 * kDamping / kMass, 1e-9 * kDamping / kMass);
}

}  // namespace
}  // namespace contactlaws::internal
