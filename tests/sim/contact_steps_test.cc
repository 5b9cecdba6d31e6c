// Copyright contactlaws authors.
//
// The steps the auto timestep gives a contact (sim/contact_steps.h), which
// `check` reports: the accuracy's steps per contact and the elastic contact
// duration, against their closed forms.

#include "sim/contact_steps.h"

#include <cmath>

#include <gtest/gtest.h>

#include "contactlaws/contactlaws.h"
#include "mujoco_test_util.h"
#include "sim/estimate.h"

namespace contactlaws {
namespace {

class ContactStepsTest : public testing::MujocoTest {};

TEST_F(ContactStepsTest, TheAccuracySetsTheStepsPerContactOfEachFamily) {
  const ContactSteps steps(kDefaultAccuracy);
  const LawId flores = *ParseLawName("flores");
  const LawId kelvin = *ParseLawName("kelvin-voigt");
  EXPECT_EQ(steps.PerContact(flores), kDefaultStepsPerContact);
  EXPECT_EQ(steps.PerContact(kelvin), kKelvinVoigtStepsAtDefault);
  EXPECT_EQ(steps.NormalStep(flores, 1e-3), 1e-3 / kDefaultStepsPerContact);
  EXPECT_EQ(steps.NormalStep(kelvin, 1e-3), 1e-3 / kKelvinVoigtStepsAtDefault);
  // a tangential period is twice its duration, divided as a contact is
  EXPECT_EQ(steps.TangentialStep(1e-3), 2e-3 / kDefaultStepsPerContact);
  // a finer accuracy, more steps: 50 (10)^0.45 for the Hertz family
  EXPECT_NEAR(ContactSteps(1e-4).PerContact(flores), 50 * std::pow(10.0, 0.45), 1e-9);
}

TEST_F(ContactStepsTest, APairsFineStepIsItsHertzDurationOverTheSteps) {
  Simulation& sim = MakeSceneSimulation("bouncing_ball.xml");
  const ContactModel& cm = sim.contact_model();
  const double mass = PairEffectiveMass(cm, 0);
  const PairSteps steps(cm, {mass}, ContactSteps(kDefaultAccuracy));
  const LawParams& law = cm.pairs()[0].params;
  // the duration at 1 m/s scaled by v^((1 - n) / (1 + n)) against Hertz's
  // at v: equal but for the rounding of pow (1e-12 relative)
  constexpr double kRounding = 1e-12;
  for (double v : {0.1, 4.2}) {
    const double hertz = HertzContactDuration(law.stiffness, law.exponent, mass, v);
    EXPECT_NEAR(steps.Fine(0, v) / (hertz / kDefaultStepsPerContact), 1.0, kRounding) << v;
  }
  // below the law's floor of v0, the floor's
  EXPECT_EQ(steps.Fine(0, 0.0), steps.Fine(0, law.min_impact_velocity));
  const double floor = HertzContactDuration(law.stiffness, law.exponent, mass,
                                            law.min_impact_velocity);
  EXPECT_NEAR(steps.Settled(0) / (floor / kSettledStepsPerContact), 1.0, kRounding);
}

}  // namespace
}  // namespace contactlaws
