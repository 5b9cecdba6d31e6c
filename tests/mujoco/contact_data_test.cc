// Copyright contactlaws authors.
//
// The hooks: untagged pairs exactly as MuJoCo, callbacks restored and
// chained, no state shared between mjData, drives exact at any time.
// Resets and divergence: contact_data_reset_test.cc.

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mujoco/hooks.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class HooksTest : public testing::MujocoTest {};

// Untagged geoms of every kind the default filter decides: contype and
// conaffinity that match one way only or not at all, a parent-child pair, a
// pair of the same body, boxes resting on the floor; plus an optional
// tagged ball far from them.
std::string UntaggedXml(bool filterparent, bool with_tag) {
  return fmt::format(R"(
<mujoco>
  <option timestep="2e-3"><flag filterparent="{fp}"/></option>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body pos="0 0 0.3"><freejoint/>
      <geom type="box" size="0.1 0.1 0.1" mass="1"/>
      <geom type="sphere" size="0.1" pos="0.1 0 0" mass="0.1"/>
      <body pos="0 0 0.25"><joint type="hinge" axis="1 0 0"/>
        <geom type="capsule" size="0.05 0.1" mass="0.2"/></body>
    </body>
    <body pos="1 0 0.3"><freejoint/>
      <geom type="box" size="0.1 0.1 0.1" contype="2" conaffinity="2" mass="1"/></body>
    <body pos="1 0 0.6"><freejoint/>
      <geom type="sphere" size="0.1" contype="2" conaffinity="1" mass="1"/></body>
    <body pos="2 0 0.3"><freejoint/>
      <geom type="sphere" size="0.1" contype="0" conaffinity="1" mass="1"/></body>
    {tagged}
  </worldbody>
  {custom}
</mujoco>)",
                     fmt::arg("fp", filterparent ? "enable" : "disable"),
                     fmt::arg("tagged", with_tag ? R"(<body pos="4 4 0.3"><freejoint/>
      <geom name="tagged" type="sphere" size="0.1" mass="1"/></body>)"
                                                 : ""),
                     fmt::arg("custom", with_tag ? R"(<custom><text name="contactlaw:t"
      data="geom1=tagged geom2=floor law=hertz stiffness=1e7"/></custom>)"
                                                 : ""));
}

TEST_F(HooksTest, UntaggedPairsBehaveExactlyAsWithoutTheLibrary) {
  for (bool filterparent : {true, false}) {
    UniqueModel m = Load(UntaggedXml(filterparent, false));
    mjData* plain = MakeData(m.get());
    mjData* hooked = MakeData(m.get());
    ContactModel cm(m.get(), "untagged");
    ContactData contacts(cm, hooked);
    int max_contacts = 0;
    for (int i = 0; i < 500; ++i) {
      mj_step(m.get(), plain);
      contacts.Step();
      ASSERT_EQ(plain->ncon, hooked->ncon) << "step " << i;
      max_contacts = std::max(max_contacts, plain->ncon);
    }
    // bit for bit: the filter reproduces MuJoCo's rule, the hook adds nothing
    EXPECT_EQ(std::memcmp(plain->qpos, hooked->qpos, sizeof(mjtNum) * m->nq), 0);
    EXPECT_EQ(std::memcmp(plain->qvel, hooked->qvel, sizeof(mjtNum) * m->nv), 0);
    EXPECT_GT(max_contacts, 4) << "the scene must actually collide";
  }
}

TEST_F(HooksTest, TaggedPairsLeaveOtherContactsAlone) {
  // the same untagged bodies next to a tagged ball: same MuJoCo contacts,
  // minus the tagged pair's
  UniqueModel plain_model = Load(UntaggedXml(true, false));
  UniqueModel tagged_model = Load(UntaggedXml(true, true));
  mjData* plain = MakeData(plain_model.get());
  mjData* tagged = MakeData(tagged_model.get());
  ContactModel cm(tagged_model.get(), "tagged");
  ContactData contacts(cm, tagged);
  const int ball = mj_name2id(tagged_model.get(), mjOBJ_GEOM, "tagged");
  for (int i = 0; i < 300; ++i) {
    mj_step(plain_model.get(), plain);
    contacts.Step();
    // MuJoCo's own contacts, and the tagged ball's listed outside the solver
    int active = 0;
    for (int c = 0; c < tagged->ncon; ++c) {
      const mjContact& con = tagged->contact[c];
      const bool ours = con.geom1 == ball || con.geom2 == ball;
      EXPECT_EQ(con.exclude != 0, ours) << "step " << i;
      active += !ours;
    }
    ASSERT_EQ(plain->ncon, active) << "step " << i;
  }
  // the tagged ball rests on its law, not on a MuJoCo constraint
  EXPECT_GE(contacts.impacts().size(), 1u);
}

int previous_filter_calls = 0;
int previous_passive_calls = 0;
int PreviousFilter(const mjModel* m, mjData*, int g1, int g2) {
  ++previous_filter_calls;
  return DefaultContactFilter(m, g1, g2);
}
void PreviousPassive(const mjModel*, mjData*) { ++previous_passive_calls; }

TEST_F(HooksTest, CallbacksFoundBeforeAreChainedAndRestored) {
  mjcb_contactfilter = PreviousFilter;
  mjcb_passive = PreviousPassive;
  previous_filter_calls = previous_passive_calls = 0;
  {
    UniqueModel m = Load(UntaggedXml(true, true));
    ContactModel cm(m.get(), "chain");
    mjData* d = MakeData(m.get());
    ContactData contacts(cm, d);
    EXPECT_NE(mjcb_contactfilter, PreviousFilter);
    EXPECT_NE(mjcb_passive, PreviousPassive);
    for (int i = 0; i < 10; ++i) contacts.Step();
    EXPECT_GT(previous_filter_calls, 0) << "untagged pairs go to the previous filter";
    EXPECT_GE(previous_passive_calls, 10) << "the previous passive hook runs too";
  }
  EXPECT_EQ(mjcb_contactfilter, PreviousFilter);
  EXPECT_EQ(mjcb_passive, PreviousPassive);
  mjcb_contactfilter = nullptr;
  mjcb_passive = nullptr;
}

TEST_F(HooksTest, OneMjDataOneContactData) {
  UniqueModel m = Load(UntaggedXml(true, true));
  ContactModel cm(m.get(), "twice");
  mjData* d = MakeData(m.get());
  ContactData first(cm, d);
  EXPECT_THROW(ContactData second(cm, d), Error);
}

TEST_F(HooksTest, DataOfOneModelShareNothing) {
  // two mjData of one model, stepped interleaved, each with its own memory,
  // end exactly where one alone ends
  const std::string xml = testing::DropXml(
      "law=flores restitution=0.5 stiffness=1.4e8", 3.0);
  UniqueModel m = Load(xml);
  ContactModel cm(m.get(), "shared");
  mjData* alone = MakeData(m.get());
  mjData* a = MakeData(m.get());
  mjData* b = MakeData(m.get());
  for (mjData* d : {alone, a, b}) mj_resetDataKeyframe(m.get(), d, 0);
  b->qvel[2] = -1.0;  // b differs: a different impact velocity
  {
    ContactData only(cm, alone);
    for (int i = 0; i < 3000; ++i) only.Step();
    ASSERT_EQ(only.impacts().size(), 1u);
  }
  ContactData ca(cm, a);
  ContactData cb(cm, b);
  for (int i = 0; i < 3000; ++i) {
    ca.Step();
    cb.Step();
  }
  EXPECT_EQ(std::memcmp(alone->qpos, a->qpos, sizeof(mjtNum) * m->nq), 0);
  EXPECT_EQ(std::memcmp(alone->qvel, a->qvel, sizeof(mjtNum) * m->nv), 0);
  ASSERT_EQ(cb.impacts().size(), 1u);
  EXPECT_NEAR(cb.impacts()[0].impact_velocity, 1.0, 1e-3);
}

TEST_F(HooksTest, ModelsShareNothing) {
  // the paper's two scenes stepped interleaved end exactly where each ends
  // alone
  const std::string dir = std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/";
  auto run = [&](Simulation* sim) {
    for (int i = 0; i < 50000; ++i) sim->Step();
  };
  Simulation ball_alone(LoadModelFile(dir + "bouncing_ball.xml"), "ball");
  run(&ball_alone);
  Simulation table_alone(LoadModelFile(dir + "ball_table.xml"), "table");
  run(&table_alone);
  Simulation ball(LoadModelFile(dir + "bouncing_ball.xml"), "ball");
  Simulation table(LoadModelFile(dir + "ball_table.xml"), "table");
  for (int i = 0; i < 50000; ++i) {
    ball.Step();
    table.Step();
  }
  for (auto [a, b] : {std::pair{&ball, &ball_alone}, std::pair{&table, &table_alone}}) {
    EXPECT_EQ(std::memcmp(a->data()->qpos, b->data()->qpos, sizeof(mjtNum) * a->model()->nq), 0);
    EXPECT_EQ(a->contacts().impacts().size(), b->contacts().impacts().size());
    CheckNoWarnings(a->data());
  }
  EXPECT_GE(ball.contacts().impacts().size(), 1u);
  EXPECT_GE(table.contacts().impacts().size(), 1u);
}

// The unload check: a process that leaks a ContactData and exits must find
// the callbacks it had before ours once the library's static destructors have
// run. ELF destructor functions run after them (after every atexit handler).
bool check_callbacks_at_exit = false;
void SentinelPassive(const mjModel*, mjData*) {}

__attribute__((destructor)) void CheckCallbacksAtExit() {
  if (check_callbacks_at_exit) _exit(mjcb_passive == SentinelPassive ? 42 : 43);
}

TEST_F(HooksTest, CallbacksAreRestoredWhenTheLibraryIsUnloaded) {
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    mjcb_passive = SentinelPassive;
    UniqueModel m = LoadModelString(testing::DropXml("law=hertz stiffness=1e8", 1.0), "leak.xml");
    auto* cm = new ContactModel(m.release(), "leak.xml");
    mjData* d = mj_makeData(cm->model());
    new ContactData(*cm, d);  // leaked on purpose: never unregistered
    if (mjcb_passive == SentinelPassive) _exit(44);  // ours must be installed now
    check_callbacks_at_exit = true;
    std::exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 42) << "43: ours still installed at exit; 44: never installed";
}

TEST_F(HooksTest, ThePassiveHookEvaluatesOnlyThePairsTheBroadphaseProposed) {
  // six balls under one group tag: 15 ball-ball pairs and 6 ball-floor pairs.
  // Planes are always proposed by MuJoCo's broadphase; balls only when their
  // bounding boxes meet
  std::string bodies;
  for (int i = 0; i < 6; ++i) {
    const double x = i < 5 ? i * 1.0 : 0.15;  // the sixth next to the first
    bodies += fmt::format(R"(<body pos="{} 0 {}"><freejoint/>
      <geom type="sphere" size="0.1" group="3" mass="1"/></body>)",
                          x, i < 5 ? 0.5 : 0.7);
  }
  UniqueModel m = Load(fmt::format(R"(<mujoco>
  <option gravity="0 0 0"/>
  <worldbody><geom name="floor" type="plane" size="5 5 0.1" group="2"/>{}</worldbody>
  <custom>
    <text name="contactlaw:balls" data="geom1=group:3 geom2=group:3 law=hertz stiffness=1e7"/>
    <text name="contactlaw:floor" data="geom1=group:3 geom2=group:2 law=hertz stiffness=1e7"/>
  </custom>
</mujoco>)", bodies));
  ContactModel cm(m.get(), "balls");
  ASSERT_EQ(cm.pairs().size(), 21u);
  mjData* d = MakeData(m.get());
  ContactData contacts(cm, d);
  mj_forward(m.get(), d);
  // the 6 floor pairs and the one pair of neighbours
  std::vector<int> expected;
  for (int p = 0; p < 21; ++p) {
    const GeomPair& pair = cm.pairs()[p];
    const bool floor = m->geom_type[pair.geom[0]] == mjGEOM_PLANE;
    const bool neighbours = std::set<int>{pair.body[0], pair.body[1]} == std::set<int>{1, 6};
    if (floor || neighbours) expected.push_back(p);
  }
  ASSERT_EQ(expected.size(), 7u);
  EXPECT_EQ(contacts.proposed_pairs(), expected);
  // apart, the neighbours are no longer proposed
  d->qpos[7 * 5 + 0] = 10.0;
  mj_forward(m.get(), d);
  EXPECT_EQ(contacts.proposed_pairs().size(), 6u);
}

TEST_F(HooksTest, PlainMjStepIsWarnedAboutOnce) {
  UniqueModel m = Load(testing::DropXml("law=hertz stiffness=1e8", 1.0, "RK4"));
  ContactModel cm(m.get(), "drop");
  mjData* d = MakeData(m.get());
  ContactData contacts(cm, d);
  // the library's own loop, and mj_forward at one time, are not warned about
  for (int i = 0; i < 100; ++i) contacts.Step();
  for (int i = 0; i < 100; ++i) mj_forward(m.get(), d);
  EXPECT_EQ(CountMujocoWarnings(""), 0u);
  // plain mj_step is, once
  for (int i = 0; i < 100; ++i) mj_step(m.get(), d);
  EXPECT_EQ(ExpectMujocoWarning("stepped without ContactData::BeforeStep/AfterStep"), 1u);
}

}  // namespace
// A scene whose every pair is tagged finds its contacts without MuJoCo's
// broadphase (its collision pass off in the data's options): the same
// contacts, in the same order, as through the broadphase's proposals, which a
// fixed box out of every ball's reach forces (an untagged pair that never
// touches). Three balls dropped on a tumbling box on the floor: multi-point
// pairs, ball-ball and ball-box contacts.
TEST_F(HooksTest, OwnBroadphaseFindsTheContactsTheBroadphaseProposes) {
  auto scene = [](bool untagged) {
    return fmt::format(R"(<mujoco>
  <option timestep="2e-4" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1" group="2"/>
    {}
    <body pos="0 0 0.15" euler="10 20 0"><freejoint/>
      <geom type="box" size="0.1 0.1 0.1" mass="1" group="3"/></body>
    <body pos="0.02 0 0.45"><freejoint/><geom type="sphere" size="0.05" mass="0.2" group="3"/></body>
    <body pos="-0.03 0.01 0.6"><freejoint/><geom type="sphere" size="0.05" mass="0.2" group="3"/></body>
    <body pos="0.2 0.01 0.3"><freejoint/><geom type="sphere" size="0.05" mass="0.2" group="3"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:bodies" data="geom1=group:3 geom2=group:3 law=hunt-crossley
      restitution=0.5 stiffness=1e6 friction=coulomb mu=0.4"/>
    <text name="contactlaw:floor" data="geom1=group:3 geom2=group:2 law=hunt-crossley
      restitution=0.5 stiffness=1e6 friction=coulomb mu=0.4"/>
  </custom>
</mujoco>)",
                       untagged ? R"(<geom name="far" type="box" size="0.1 0.1 0.1" pos="50 0 5"/>)"
                                : "");
  };
  std::vector<mjtNum> qpos[2];
  int points = 0;
  for (bool untagged : {false, true}) {
    UniqueModel m = Load(scene(untagged));
    ContactModel cm(m.get(), "scene");
    mjData* d = MakeData(m.get());
    ContactData contacts(cm, d);
    EXPECT_EQ((contacts.options().disableflags & mjDSBL_CONTACT) != 0, !untagged);
    for (int i = 0; i < 3000; ++i) {
      contacts.Step();
      points = std::max(points, static_cast<int>(contacts.latest().size()));
    }
    qpos[untagged].assign(d->qpos, d->qpos + m->nq);
  }
  EXPECT_GE(points, 5) << "the box's corners and the balls must be in contact at once";
  EXPECT_EQ(std::memcmp(qpos[0].data(), qpos[1].data(), sizeof(mjtNum) * qpos[0].size()), 0);
}

}  // namespace contactlaws
