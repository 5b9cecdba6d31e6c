// Copyright contactlaws authors.
//
// The sub-step rule of ContactStepper (docs/timestep.md, "Contact steps") on
// points built by hand: which points set how many sub-steps in a 2 ms step.
// Each test compares the step with and without the point or state under
// test, so that what it shows is that point's own share.

#include "mujoco/contact_stepper.h"

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws::internal {
namespace {

// A 10 cm cube of 1 kg above a floor, frictionless Hunt-Crossley (e = 0.5,
// K = 1e7 N/m^1.5), at MuJoCo's default 2 ms step.
constexpr double kHalf = 0.05;      // m
constexpr double kStiffness = 1e7;  // N/m^1.5
constexpr double kStep = 2e-3;      // s

class ContactStepperTest : public testing::MujocoTest {
 protected:
  void SetUp() override {
    MujocoTest::SetUp();
    model_ = Load(fmt::format(R"(<mujoco>
  <option timestep="{2}" integrator="Euler"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="cube" pos="0 0 {0}"><freejoint/>
      <geom name="cube" type="box" size="{0} {0} {0}" mass="1"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:floor-cube" data="geom1=floor geom2=cube law=hunt-crossley
      restitution=0.5 stiffness={1} min_impact_velocity=0.01"/>
  </custom>
</mujoco>)",
                              kHalf, kStiffness, kStep));
    contact_model_ = std::make_unique<ContactModel>(model_.get(), "cube");
    d_ = MakeData(model_.get());
  }

  // Places the cube with its bottom at height z (m) and velocity qvel (6),
  // forwarded.
  void Place(double z, const std::vector<double>& qvel) {
    d_->qpos[2] = z + kHalf;
    for (int k = 0; k < 6; ++k) d_->qvel[k] = qvel[k];
    Forward();
  }

  // mj_forward without MuJoCo's own contact, which a run's contact filter
  // removes (the stepper reads qfrc_constraint as the other constraints'
  // force)
  void Forward() {
    mj_forward(model_.get(), d_);
    mju_zero(d_->qfrc_constraint, model_->nv);
  }

  // A point of the floor-cube pair at (x, y) on the floor: depth d (m),
  // depth rate (m/s), weight w, its episode's v0 (m/s), the depth's gradient
  // (the normal +z but for a face patch's sliding point), the law's force.
  PointEvaluation Point(double x, double y, double depth, double rate, double weight = 1,
                        double v0 = 0.01, const std::vector<double>& gradient = {0, 0, 1}) {
    PointEvaluation e;
    e.pair = 0;
    e.tag = 0;
    e.episode = 0;
    e.touch = false;
    e.depth = depth;
    e.depth_rate = rate;
    e.weight = weight;
    e.impact_velocity = v0;
    e.max_approach = std::max(rate, 0.0);
    const double pos[3] = {x, y, -depth / 2};
    const double normal[3] = {0, 0, 1};
    for (int k = 0; k < 3; ++k) {
      e.pos[k] = pos[k];
      e.normal[k] = normal[k];
      e.gradient[k] = gradient[k];
    }
    if (depth > 0) {
      const ContactState state{depth, rate, v0, 0.0};
      e.force = weight * EvaluateLaw(contact_model_->pairs()[0].params, state).total;
    }
    return e;
  }

  // A point out of contact by gap (m), as the evaluator adds it
  // (ContactStepper::AddNear).
  void AddNear(ContactStepper* stepper, double x, double y, double gap) {
    mjContact con{};
    con.dist = gap;
    con.pos[0] = x;
    con.pos[1] = y;
    con.pos[2] = gap / 2;
    con.frame[2] = 1;
    con.geom1 = contact_model_->pairs()[0].geom[0];
    con.geom2 = contact_model_->pairs()[0].geom[1];
    const mjtNum gradient[3] = {0, 0, 1};
    stepper->AddNear(d_, 0, con, 1.0, gradient);
  }

  // The sub-steps of one step from d_'s state with points touching (and
  // near, when given), under --contact-steps auto.
  int SubSteps(const std::vector<PointEvaluation>& touching, double near_gap = 0,
               double near_x = 0, double near_y = 0) {
    ContactStepper stepper(*contact_model_);
    ContactStepsOptions options;
    options.substeps = kContactStepsAuto;
    stepper.set_options(options);
    std::vector<double> qpos(d_->qpos, d_->qpos + model_->nq);
    std::vector<double> qvel(d_->qvel, d_->qvel + model_->nv);
    stepper.Clear();
    if (near_gap > 0) AddNear(&stepper, near_x, near_y, near_gap);
    stepper.Integrate(model_.get(), d_, touching);
    const int substeps = stepper.substeps();
    // the next measure starts from the same state
    std::copy(qpos.begin(), qpos.end(), d_->qpos);
    std::copy(qvel.begin(), qvel.end(), d_->qvel);
    Forward();
    return substeps;
  }

  UniqueModel model_;
  std::unique_ptr<ContactModel> contact_model_;
  mjData* d_ = nullptr;
};

TEST_F(ContactStepperTest, APointOfNoWeightOnALongGradientSetsNoSubStep) {
  // a face patch's point sliding off the face (weight 1e-6, its gradient 30
  // times longer than the normal across it) beside two corners that carry
  // the cube: A_ii of its row is 900 times a corner's, but the force it
  // can carry is a millionth of theirs. With A weighed by the points'
  // weights it adds no sub-steps; unweighed, it set 14 times as many (461
  // against 33).
  // two corners at the depth where each carries half the weight
  const double depth = std::pow(9.81 / 2 / kStiffness, 1 / 1.5);
  Place(-depth, {0, 0, 0, 0, 0, 0});
  const std::vector<PointEvaluation> corners = {Point(-kHalf, -kHalf, depth, 0.02, 1, 0.5),
                                                Point(kHalf, -kHalf, depth, 0.02, 1, 0.5)};
  const int alone = SubSteps(corners);
  std::vector<PointEvaluation> with = corners;
  with.push_back(Point(kHalf, kHalf, depth, 0.02, 1e-6, 0.5, {30, 0, 1}));
  const int beside = SubSteps(with);
  EXPECT_GT(alone, 1);
  // the weightless point's coupling adds sqrt(1e-6) 30 A_ij to a corner's
  // sum: below 10% more sub-steps
  EXPECT_LE(beside, std::ceil(1.1 * alone)) << "alone " << alone;
}

TEST_F(ContactStepperTest, APointVibratingInContactTakesItsSubStepsFromItsVibration) {
  // the four bottom corners at their static depth (each a quarter of the
  // weight), vibrating by 30% of it, in an episode that began with a push at
  // 0.3 m/s: their sub-step is a quarter radian of their vibration, not a
  // twentieth of a 0.3 m/s impact's duration, as when the same corners are
  // struck at 0.3 m/s now (their rate). Before the rule, both took the
  // impact's sub-steps (36 at 50 per contact).
  const double depth = std::pow(9.81 / 4 / kStiffness, 1 / 1.5);
  Place(-depth, {0, 0, 0, 0, 0, 0});
  // the rate that makes the vibration's amplitude 30% of the depth: |d'| / w
  // with w^2 = 1.5 K d^0.5 A_ii, A_ii = 4 / m for a corner of a cube (1/m,
  // and 3/m of its turn)
  const double w = std::sqrt(1.5 * kStiffness * std::sqrt(depth) * 4.0);
  const double rate = 0.3 * depth * w;
  std::vector<PointEvaluation> vibrating, struck;
  for (const double x : {-kHalf, kHalf}) {
    for (const double y : {-kHalf, kHalf}) {
      vibrating.push_back(Point(x, y, depth, x * y > 0 ? rate : -rate, 1, 0.3));
      struck.push_back(Point(x, y, depth, 0.3, 1, 0.3));
    }
  }
  const int vibrating_steps = SubSteps(vibrating);
  const int struck_steps = SubSteps(struck);
  EXPECT_GT(vibrating_steps, 1);
  // A's row sum for a corner is 8 / m: the impact's 20 sub-steps per
  // contact duration at 0.3 m/s on 1/8 kg (1.4e-4 s each) against 0.25 rad
  // of the vibration at twice the depth (2.4e-4 s): 1.7 times fewer; at
  // least 1.5
  EXPECT_LT(1.5 * vibrating_steps, struck_steps) << "vibrating " << vibrating_steps;
}

TEST_F(ContactStepperTest, APointTheStepCannotCloseSetsNoSubStep) {
  // the cube lands on one corner falling at 0.3 m/s and turning at -2 rad/s
  // about y: that corner approaches at 0.4 m/s, the far one across the
  // bottom face at 0.2 m/s. 4 mm above the floor, the far corner is within
  // the narrowphase's reach (the cube's spin times its bounding radius) but
  // the step closes at most twice 0.2 m/s 2 ms and its acceleration's
  // share, 0.9 mm: it cannot touch within the step and adds no sub-step.
  // 0.1 mm above the floor it can, and does.
  Place(0, {0, 0, -0.3, 0, -2, 0});
  const std::vector<PointEvaluation> corner = {Point(-kHalf, 0, 1e-6, 0.4, 1, 0.4)};
  const int alone = SubSteps(corner);
  const int far = SubSteps(corner, 4e-3, kHalf, 0);
  const int near = SubSteps(corner, 1e-4, kHalf, 0);
  EXPECT_EQ(far, alone);
  EXPECT_GT(near, alone);
}

}  // namespace
}  // namespace contactlaws::internal
