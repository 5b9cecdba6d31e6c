// Copyright contactlaws authors.
//
// DamperRate against the rigid-body closed forms: a point at r
// from a free body's centre of mass moves, per unit impulse along t (a
// tangent, or the normal), by 1/m + (r x t) . I^-1 (r x t).

#include "mujoco/damper_rate.h"

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws::internal {
namespace {

// The definition's rate: the largest eigenvalue of the n x n matrix
// C^(1/2) P J M^-1 J^T P C^(1/2) over all of the model's dofs, n = 3 points,
// J the points' relative Jacobians, P the projections.
double DefinitionRate(const mjModel* m, mjData* d, const GeomPair& pair, int points,
                      const mjtNum* pos, const mjtNum* normal, const double* damping,
                      DamperDirection direction) {
  using Matrix = Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const int nv = m->nv, n = 3 * points;
  Matrix rows(n, nv), jac[2] = {Matrix(3, nv), Matrix(3, nv)};
  for (int j = 0; j < points; ++j) {
    for (int b = 0; b < 2; ++b) mj_jac(m, d, jac[b].data(), nullptr, pos + 3 * j, pair.body[b]);
    const Eigen::Map<const Eigen::Vector3<mjtNum>> unit(normal + 3 * j);
    Eigen::Matrix3<mjtNum> projection = unit * unit.transpose();
    if (direction == DamperDirection::kTangential) {
      projection = Eigen::Matrix3<mjtNum>::Identity() - projection;
    }
    rows.middleRows(3 * j, 3) = std::sqrt(damping[j]) * projection * (jac[1] - jac[0]);
  }
  Matrix inverse_rows(n, nv);  // M^-1 rows^T, row by row
  mj_solveM(m, d, inverse_rows.data(), rows.data(), n);
  const Eigen::MatrixX<mjtNum> product = rows * inverse_rows.transpose();
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixX<mjtNum>>(product, Eigen::EigenvaluesOnly)
      .eigenvalues()
      .maxCoeff();
}

class DamperRateTest : public testing::MujocoTest {
 protected:
  // A cube of half size kCubeHalf as Body (centred at z = 1): its four
  // bottom corners, each with the floor's normal and a damper kDamping.
  static constexpr double kCubeHalf = 0.01;  // m
  struct Corners {
    mjData* d = nullptr;
    std::vector<mjtNum> pos, normal;
    std::vector<double> damping = std::vector<double>(4, kDamping);
  };
  Corners CubeOnItsCorners() {
    Corners c;
    c.d = Body(fmt::format(R"(type="box" size="{0} {0} {0}")", kCubeHalf));
    for (const double x : {-kCubeHalf, kCubeHalf}) {
      for (const double y : {-kCubeHalf, kCubeHalf}) {
        c.pos.insert(c.pos.end(), {x, y, 1 - kCubeHalf});
        c.normal.insert(c.normal.end(), {0, 0, 1});
      }
    }
    return c;
  }

  // A free body of mass kMass (its geom given) at z = 1 above a static
  // floor, forwarded.
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
  const Corners cube = CubeOnItsCorners();
  DamperRate rate;
  EXPECT_NEAR(rate.Rate(model_.get(), cube.d, pair_, 4, cube.pos.data(), cube.normal.data(),
                        cube.damping.data()),
              12 * kDamping / kMass, 1e-9 * kDamping / kMass);
  // the normal's own direction is not damped: a normal along x leaves y, z
  const mjtNum side[3] = {1, 0, 0};
  const mjtNum centre[3] = {0, 0, 1};
  EXPECT_NEAR(rate.Rate(model_.get(), cube.d, pair_, 1, centre, side, &kDamping), kDamping / kMass,
              1e-9 * kDamping / kMass);
  // their normal dampers: the cube rises against 4 c on m (4 c / m) and
  // rocks about a horizontal axis against 4 c a^2 on I_xx = 2/3 m a^2
  // (6 c / m), the fastest mode
  EXPECT_NEAR(rate.Rate(model_.get(), cube.d, pair_, 4, cube.pos.data(), cube.normal.data(),
                        cube.damping.data(), DamperDirection::kNormal),
              6 * kDamping / kMass, 1e-9 * kDamping / kMass);
}

TEST_F(DamperRateTest, TheBoundIsTheFrobeniusNormOfTheRatesMatrix) {
  // the cube's four bottom corners and their normal dampers: it rises at
  // 4 c / m and rocks about x and y at 6 c / m, and nothing else moves
  // against them; the bound is sqrt(4^2 + 6^2 + 6^2) c / m, and its margin,
  // 1e-9 of the trace (4 + 6 + 6) c / m
  const Corners cube = CubeOnItsCorners();
  DamperRate rate;
  const double bound =
      rate.Bound(model_.get(), cube.d, pair_, 4, cube.pos.data(), cube.normal.data(),
                 cube.damping.data(), DamperDirection::kNormal);
  EXPECT_NEAR(bound, (std::sqrt(88.0) + 16e-9) * kDamping / kMass, 1e-12 * kDamping / kMass);
  EXPECT_GE(bound, rate.Rate(model_.get(), cube.d, pair_, 4, cube.pos.data(), cube.normal.data(),
                             cube.damping.data(), DamperDirection::kNormal));
  // friction's dampers there, along a tilted normal (a corner on a slope):
  // above the exact rate, within sqrt(6) of it (six dofs: the rank) and the
  // margin
  const std::vector<mjtNum> tilted = {0.6, 0, 0.8, 0.6, 0, 0.8, 0.6, 0, 0.8, 0.6, 0, 0.8};
  const std::vector<mjtNum>* normals[] = {&cube.normal, &tilted};
  for (const std::vector<mjtNum>* n : normals) {
    const double exact =
        rate.Rate(model_.get(), cube.d, pair_, 4, cube.pos.data(), n->data(), cube.damping.data());
    const double tangential = rate.Bound(model_.get(), cube.d, pair_, 4, cube.pos.data(), n->data(),
                                         cube.damping.data(), DamperDirection::kTangential);
    EXPECT_GE(tangential, exact);
    EXPECT_LE(tangential, std::sqrt(6.0) * exact * (1 + 1e-8));
    // the exact rate from Bound's rows: Rate's, to the bit
    EXPECT_EQ(rate.RateAfterBound(model_.get()), exact);
  }
}

TEST_F(DamperRateTest, TheInertiaBoundTakesEachPointsDistanceOnTheSmallestMoment) {
  // the cube's four bottom corners, at sqrt(3) a from its centre, I = 2/3 m
  // a^2: each point moves at most by 1/m + 3 a^2 / I = 5.5 / m per unit
  // force; the normal dampers' bound 4 x 5.5 c / m (above the rate, 6 c / m),
  // friction's twice that (two rows per point), and Bound's margin
  const Corners cube = CubeOnItsCorners();
  DamperRate rate;
  EXPECT_NEAR(rate.InertiaBound(model_.get(), cube.d, pair_, 4, cube.pos.data(),
                                cube.damping.data(), DamperDirection::kNormal),
              22 * (1 + 1e-9) * kDamping / kMass, 1e-12 * kDamping / kMass);
  EXPECT_NEAR(rate.InertiaBound(model_.get(), cube.d, pair_, 4, cube.pos.data(),
                                cube.damping.data(), DamperDirection::kTangential),
              44 * (1 + 1e-9) * kDamping / kMass, 1e-12 * kDamping / kMass);
  // a body hinged to another: its inertia is not its own, no bound
  model_ = Load(R"(<mujoco><worldbody><body pos="0 0 1"><freejoint/>
    <geom type="box" size="0.01 0.01 0.01" mass="0.01"/>
    <body pos="0.02 0 0"><joint type="hinge"/><geom type="sphere" size="0.01" mass="0.01"/>
    </body></body></worldbody></mujoco>)");
  mjData* hinged = MakeData(model_.get());
  mj_forward(model_.get(), hinged);
  EXPECT_EQ(rate.InertiaBound(model_.get(), hinged, pair_, 4, cube.pos.data(), cube.damping.data(),
                              DamperDirection::kNormal),
            std::numeric_limits<double>::infinity());
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

TEST_F(DamperRateTest, AgreesWithTheDefinitionsSolveOnRandomPointsOfOneAndTwoBodies) {
  // Rate solves the smaller of the two Gram matrices of the points' rows,
  // one per point and damped direction, over the two bodies' trees' dofs (a
  // cube's 4 corners: 6 x 6, not the definition's 12 x 12).
  // Two backward-stable symmetric eigenvalue solves of matrices equal in
  // exact arithmetic agree to some n eps lambda_max each (Weyl: a perturbed
  // symmetric matrix's eigenvalues move by at most the perturbation's norm;
  // the products' roundings are of the same order), n <= 18 here: a few
  // hundred roundings at most; 1e-12 of lambda_max is thousands.
  constexpr double kAgreement = 1e-12;
  model_ = Load(R"(<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body pos="0 0 1" quat="0.9 0.3 -0.2 0.1"><freejoint/>
      <geom type="box" size="0.05 0.03 0.02" mass="0.37"/></body>
    <body pos="0.3 0 1"><freejoint/><geom type="sphere" size="0.05" mass="0.2"/></body>
    <body pos="0.6 0 1"><freejoint/><geom type="box" size="0.04 0.04 0.04" mass="1.3"/></body>
  </worldbody>
</mujoco>)");
  mjData* d = MakeData(model_.get());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1), positive(0.1, 100);
  int smaller = 0;  // the solves where the Gram matrix of the dofs is the smaller
  for (int trial = 0; trial < 200; ++trial) {
    // a random state: positions moved, orientations turned
    for (int i = 0; i < model_->nq; ++i) d->qpos[i] = model_->qpos0[i] + 0.3 * unit(random);
    mj_normalizeQuat(model_.get(), d->qpos);
    mj_forward(model_.get(), d);
    // a body on the floor (6 dofs) or against another body (12), 1 to 6 points
    GeomPair pair;
    pair.body = trial % 2 ? std::array<int, 2>{0, 1 + trial / 2 % 3}
                          : std::array<int, 2>{1 + trial / 2 % 3, 1 + (trial / 2 + 1) % 3};
    const int points = 1 + trial / 6 % 6;
    std::vector<mjtNum> pos, normal;
    std::vector<double> damping;
    for (int j = 0; j < points; ++j) {
      Eigen::Vector3<mjtNum> n(unit(random), unit(random), unit(random));
      n.normalize();
      for (int i = 0; i < 3; ++i) {
        pos.push_back(d->xpos[3 * pair.body[1] + i] + 0.05 * unit(random));
        normal.push_back(n[i]);
      }
      damping.push_back(positive(random));
    }
    for (DamperDirection direction : {DamperDirection::kTangential, DamperDirection::kNormal}) {
      const double exact = DefinitionRate(model_.get(), d, pair, points, pos.data(),
                                          normal.data(), damping.data(), direction);
      DamperRate rate;
      EXPECT_NEAR(rate.Rate(model_.get(), d, pair, points, pos.data(), normal.data(),
                            damping.data(), direction),
                  exact, kAgreement * exact)
          << "trial " << trial << ", " << points << " points";
      // the bound from the bodies' inertia is above it
      EXPECT_GE(rate.InertiaBound(model_.get(), d, pair, points, pos.data(), damping.data(),
                                  direction),
                exact)
          << "trial " << trial << ", " << points << " points";
      const int rows = (direction == DamperDirection::kNormal ? 1 : 2) * points;
      smaller += rows > (pair.body[0] == 0 ? 6 : 12);
    }
  }
  // both solves were tried (400 in all)
  EXPECT_GT(smaller, 20);
  EXPECT_LT(smaller, 380);
}

}  // namespace
}  // namespace contactlaws::internal
