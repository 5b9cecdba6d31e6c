// Copyright contactlaws authors.
//
// The hooks' per-step work allocates nothing: operator new is counted while
// the test asks (its own executable: the replacement is process-wide).

#include <cmath>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

// Counts operator new while a test asks for it (the hooks' per-step work
// must not allocate).
namespace {
thread_local bool count_allocations = false;
thread_local long allocations = 0;
}  // namespace

// (gcc cannot see that the replaced operator new below takes from malloc)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t size) {
  if (count_allocations) ++allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace contactlaws {
namespace {

class HooksTest : public testing::MujocoTest {};

TEST_F(HooksTest, StepsAllocateNothingInFlightOrInContact) {
  // RK4, so the passive hook runs four times a step; a group tag, so the
  // filter decides several pairs; Kelvin-Voigt from e, so the effective mass
  // is computed at every evaluation in contact
  UniqueModel m = Load(R"(<mujoco>
  <option timestep="1e-5" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1" group="2"/>
    <body pos="0 0 0.11"><freejoint/><geom type="sphere" size="0.1" mass="1" group="3"/></body>
    <body pos="0.5 0 0.3"><freejoint/><geom type="sphere" size="0.1" mass="1" group="3"/></body>
  </worldbody>
  <custom><text name="contactlaw:all" data="geom1=group:3 geom2=group:2 law=kelvin-voigt
    restitution=0.5 linear_stiffness=5e6"/></custom>
</mujoco>)");
  ContactModel cm(m.get(), "two balls");
  mjData* d = MakeData(m.get());
  ContactData contacts(cm, d);
  // into the first ball's contact: its episode is open
  while (contacts.impacts().empty()) contacts.Step();
  ASSERT_TRUE(contacts.impacts()[0].open);
  count_allocations = true;
  allocations = 0;
  long steps = 0;
  while (contacts.impacts()[0].open) {  // the rest of the contact ...
    contacts.Step();
    ++steps;
  }
  for (int i = 0; i < 2000; ++i) contacts.Step();  // ... and flight
  count_allocations = false;
  ASSERT_EQ(contacts.impacts().size(), 1u) << "the window must not open a new episode";
  EXPECT_GT(steps, 50);
  EXPECT_EQ(allocations, 0) << "over " << steps + 2000 << " steps";
}

TEST_F(HooksTest, SteppingAMeshCubeOnABoxAllocatesNothing) {
  // box-mesh through contactlaws' polytope kernel (mujoco/narrowphase.cc):
  // the cube resting on its 4 corners
  UniqueModel m = Load(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <asset><mesh name="cube" vertex="-.05 -.05 -.05 .05 -.05 -.05 -.05 .05 -.05 .05 .05 -.05
                                   -.05 -.05 .05 .05 -.05 .05 -.05 .05 .05 .05 .05 .05"/></asset>
  <worldbody>
    <geom name="base" type="box" size="0.2 0.2 0.1" pos="0 0 0.1"/>
    <body pos="0 0 0.25"><freejoint/><geom name="cube" type="mesh" mesh="cube" mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:cube" data="geom1=cube geom2=base law=hunt-crossley
    restitution=0.5 stiffness=1e7"/></custom>
</mujoco>)");
  ContactModel cm(m.get(), "mesh on box");
  mjData* d = MakeData(m.get());
  ContactData contacts(cm, d);
  for (int i = 0; i < 100; ++i) contacts.Step();
  count_allocations = true;
  allocations = 0;
  for (int i = 0; i < 2000; ++i) contacts.Step();
  count_allocations = false;
  EXPECT_EQ(contacts.latest().size(), 4u);
  EXPECT_EQ(allocations, 0) << "over 2000 steps";
}

TEST_F(HooksTest, SteppingASlidingThenStickingContactAllocatesNothing) {
  // a block sliding to rest under coulomb friction, with rolling and
  // torsional resistance (condim 6): the stick state is committed each step
  UniqueModel m = Load(R"(<mujoco>
  <option timestep="1e-4" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1" condim="6" friction="0.5 0.005 0.001"/>
    <body pos="0 0 0.0498"><freejoint/><geom name="box" type="box" size="0.05 0.05 0.05" mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:box" data="geom1=box geom2=floor law=hunt-crossley
    restitution=0.5 stiffness=1e6 friction=coulomb"/></custom>
</mujoco>)");
  ContactModel cm(m.get(), "sliding box");
  mjData* d = MakeData(m.get());
  d->qvel[0] = 0.5;
  ContactData contacts(cm, d);
  for (int i = 0; i < 200; ++i) contacts.Step();  // the corners' episodes open
  ASSERT_FALSE(contacts.latest().empty());
  const size_t episodes = contacts.point_episodes().size();
  count_allocations = true;
  allocations = 0;
  for (int i = 0; i < 3000; ++i) contacts.Step();  // slides (about 0.05 s) and sticks
  count_allocations = false;
  EXPECT_LT(std::abs(d->qvel[0]), 1e-3) << "the block must have stopped";
  ASSERT_EQ(contacts.point_episodes().size(), episodes) << "no new episode in the window";
  EXPECT_EQ(allocations, 0);
}

}  // namespace
}  // namespace contactlaws
