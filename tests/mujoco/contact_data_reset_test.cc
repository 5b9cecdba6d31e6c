// Copyright contactlaws authors.
//
// The hooks across a reset and a divergence: Reset() and MuJoCo's own
// mj_resetData forget the per-contact memory and the energy ledger; a
// divergence is found, named, dated at its step and forgotten by a reset.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class HooksTest : public testing::MujocoTest {};

TEST_F(HooksTest, ResetForgetsTheEpisodes) {
  Simulation& sim = MakeSimulation(testing::DropXml("law=flores restitution=0.5 stiffness=1.4e8", 3.0));
  const Episode first = testing::FirstImpact(sim);
  sim.Reset();
  EXPECT_TRUE(sim.contacts().impacts().empty());
  EXPECT_EQ(sim.time(), 0.0);
  const Episode again = testing::FirstImpact(sim);
  EXPECT_EQ(again.index, 1);
  EXPECT_EQ(again.restitution_post(), first.restitution_post());
}

TEST_F(HooksTest, MjResetDataAloneClearsThePerContactMemory) {
  // a user's loop that resets with MuJoCo's own call and never calls Reset()
  UniqueModel m = Load(testing::DropXml("law=flores restitution=0.5 stiffness=1.4e8", 3.0));
  ContactModel cm(m.get(), "drop");
  mjData* d = MakeData(m.get());
  ContactData contacts(cm, d);
  std::vector<Episode> runs[2];
  double dissipated[2];
  for (int k = 0; k < 2; ++k) {
    mj_resetDataKeyframe(m.get(), d, 0);
    while (d->time < 0.02) contacts.Step();
    runs[k] = contacts.impacts();
    dissipated[k] = contacts.DissipatedEnergy();
  }
  EXPECT_GT(dissipated[0], 0);
  EXPECT_EQ(dissipated[1], dissipated[0]) << "the energy ledger starts again";
  ASSERT_EQ(runs[0].size(), 1u);
  ASSERT_EQ(runs[1].size(), 1u) << "the first run's episode was forgotten";
  EXPECT_EQ(runs[1][0].index, 1);
  EXPECT_EQ(runs[1][0].impact_velocity, runs[0][0].impact_velocity);
  EXPECT_EQ(runs[1][0].restitution_post(), runs[0][0].restitution_post());
  EXPECT_EQ(runs[1][0].max_force, runs[0][0].max_force);

  // reset while a contact is open: the new run's first contact is a new episode
  mj_resetDataKeyframe(m.get(), d, 0);
  while (contacts.impacts().empty() || !contacts.impacts()[0].open) contacts.Step();
  mj_resetDataKeyframe(m.get(), d, 0);
  while (d->time < 0.02) contacts.Step();
  ASSERT_EQ(contacts.impacts().size(), 1u);
  EXPECT_EQ(contacts.impacts()[0].impact_velocity, runs[0][0].impact_velocity);
  EXPECT_EQ(contacts.DissipatedEnergy(), dissipated[0]);
}

TEST_F(HooksTest, DivergenceIsFoundAndNamed) {
  struct Case {
    std::string tag;
    double speed;
    const char* integrator;
    double timestep;
    Divergence::Kind kind;
  };
  const Case cases[] = {
      // elastic depth at 5 m/s would be 0.1 m, the radius: beyond half of it
      {"law=hertz stiffness=1e4", 5.0, "RK4", 1e-5, Divergence::Kind::kTooDeep},
      // the first step in contact makes qacc > 1e10: MuJoCo resets the data
      {"law=hertz stiffness=1e15", 5.0, "Euler", 1e-3, Divergence::Kind::kMujocoReset},
  };
  for (const Case& c : cases) {
    UniqueModel m = Load(testing::DropXml(c.tag, c.speed, c.integrator, c.timestep));
    ContactModel cm(m.get(), "drop");
    mjData* d = MakeData(m.get());
    mj_resetDataKeyframe(m.get(), d, 0);
    ContactData contacts(cm, d);
    while (!contacts.divergence() && d->time < 0.1 && d->time >= 0) contacts.Step();
    ASSERT_TRUE(contacts.divergence()) << c.tag;
    const Divergence& divergence = *contacts.divergence();
    EXPECT_EQ(divergence.kind, c.kind) << c.tag << ": " << divergence.what;
    EXPECT_EQ(divergence.pair, 0) << c.tag;
    EXPECT_GT(divergence.depth, 0) << c.tag;
    EXPECT_GT(divergence.time, 0) << c.tag;
    if (c.kind == Divergence::Kind::kTooDeep) {
      EXPECT_GT(divergence.depth, cm.pairs()[0].depth_limit);
      EXPECT_DOUBLE_EQ(cm.pairs()[0].depth_limit, 0.05);  // half the radius
    }
    // Reset() (or mj_resetData and a step) forgets it
    contacts.Reset();
    EXPECT_FALSE(contacts.divergence());
    if (c.kind == Divergence::Kind::kMujocoReset) {
      // MuJoCo's own warning, expected here
      ExpectMujocoWarning("Nan, Inf or huge value in QACC");
      d->warning[mjWARN_BADQACC].number = 0;
    }
  }
}

TEST_F(HooksTest, AResetAtTheStartOfAStepIsDatedThereNotAtZero) {
  UniqueModel m = Load(testing::DropXml("law=hertz stiffness=1e7", 1.0, "RK4", 1e-4));
  ContactModel cm(m.get(), "drop");
  mjData* d = MakeData(m.get());
  mj_resetDataKeyframe(m.get(), d, 0);
  ContactData contacts(cm, d);
  while (d->time < 0.01) contacts.Step();
  const double before = d->time;
  d->qvel[2] = 2 * mjMAXVAL;  // MuJoCo's check at the step's start resets the data
  contacts.Step();
  ASSERT_TRUE(contacts.divergence());
  EXPECT_EQ(contacts.divergence()->kind, Divergence::Kind::kMujocoReset);
  EXPECT_DOUBLE_EQ(contacts.divergence()->time, before);
  EXPECT_EQ(contacts.divergence()->pair, -1);  // the reset state says nothing of the contacts
  ExpectMujocoWarning("Nan, Inf or huge value in QVEL");
  d->warning[mjWARN_BADQVEL].number = 0;
}

}  // namespace
}  // namespace contactlaws
