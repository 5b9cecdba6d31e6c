// Copyright contactlaws authors.
//
// The hooks on threads: the callbacks found before ours are chained while
// ours are installed and restored when the last ContactData goes, whatever
// thread creates and destroys them; a plain mjData stepped meanwhile is left
// to MuJoCo.

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "mujoco/hooks.h"
#include "mujoco/thread_test_util.h"

namespace contactlaws {
namespace {

using testing::Barrier;
using testing::ThreadTest;

// The callbacks a program had before ours: they count their calls.
std::atomic<int64_t> sentinel_filter_calls{0};
std::atomic<int64_t> sentinel_passive_calls{0};
std::atomic<int64_t> sentinel_passive_calls_alone{0};  // with ours not installed

int SentinelFilter(const mjModel* m, mjData*, int g1, int g2) {
  sentinel_filter_calls.fetch_add(1, std::memory_order_relaxed);
  return DefaultContactFilter(m, g1, g2);
}

void SentinelPassive(const mjModel*, mjData*) {
  sentinel_passive_calls.fetch_add(1, std::memory_order_relaxed);
  // the caller holds a ContactData, so nobody writes mjcb_passive meanwhile
  if (mjcb_passive == SentinelPassive) {
    sentinel_passive_calls_alone.fetch_add(1, std::memory_order_relaxed);
  }
}

TEST_F(ThreadTest, CallbacksAreChainedAndRestoredWhateverThreadsCreateAndDestroy) {
  // a tagged ball on the floor next to an untagged box resting on it: the
  // box-floor pair goes through the filter found before ours
  const ContactModel& laws = InlineLaws(R"(
<mujoco>
  <option timestep="1e-4" gravity="0 0 -9.81"/>
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <body pos="0 0 0.1"><freejoint/>
      <geom name="ball" type="sphere" size="0.1" mass="1"/></body>
    <body pos="0.5 0 0.1"><freejoint/>
      <geom name="box" type="box" size="0.1 0.1 0.1" mass="1"/></body>
  </worldbody>
  <custom><text name="contactlaw:ball-floor"
      data="geom1=ball geom2=floor law=hunt-crossley restitution=0.5 stiffness=1e7"/></custom>
</mujoco>)",
                                        "callbacks.xml");
  const mjModel* m = laws.model();

  mjcb_contactfilter = SentinelFilter;
  mjcb_passive = SentinelPassive;
  sentinel_filter_calls = sentinel_passive_calls = sentinel_passive_calls_alone = 0;

  // each thread owns two mjData and, round after round, gives each a
  // ContactData with interleaved lifetimes (a, b made; a stepped and gone; b
  // stepped and gone), so the number alive goes up and down across threads
  // and through zero (ours installed and removed again) whenever the threads
  // drift apart; in the first round all threads wait until every
  // ContactData is alive, so lifetimes overlap across threads whatever the
  // scheduler does
  constexpr int kThreads = 4;
  constexpr int kRounds = 30;
  constexpr int kStepsPerData = 5;
  std::vector<mjData*> data;
  for (int i = 0; i < 2 * kThreads; ++i) {
    data.push_back(MakeData(m));
    mj_resetData(m, data.back());
  }
  Barrier barrier(kThreads);
  Barrier all_alive(kThreads);
  std::atomic<int> alive{0};
  std::atomic<int> most_alive{0};
  std::atomic<int> ours_missing{0};  // times a holder did not see our hooks
  auto born = [&] {
    const int now = alive.fetch_add(1) + 1;
    int most = most_alive.load();
    while (now > most && !most_alive.compare_exchange_weak(most, now)) {
    }
  };
  auto step = [&](ContactData& contacts) {
    // while this ContactData lives, the hooks are ours
    if (mjcb_passive == SentinelPassive || mjcb_contactfilter == SentinelFilter) ++ours_missing;
    for (int i = 0; i < kStepsPerData; ++i) contacts.Step();
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      barrier.Wait();
      for (int round = 0; round < kRounds; ++round) {
        auto a = std::make_unique<ContactData>(laws, data[2 * t]);
        born();
        auto b = std::make_unique<ContactData>(laws, data[2 * t + 1]);
        born();
        if (round == 0) all_alive.Wait();
        step(*a);
        a.reset();
        --alive;
        step(*b);
        b.reset();
        --alive;
      }
    });
  }
  for (std::thread& t : threads) t.join();

  EXPECT_EQ(mjcb_contactfilter, SentinelFilter);
  EXPECT_EQ(mjcb_passive, SentinelPassive);
  EXPECT_EQ(ours_missing.load(), 0);
  EXPECT_EQ(most_alive.load(), 2 * kThreads);
  // Euler: one passive evaluation per step, and ours called the sentinel in
  // each, never the sentinel alone
  EXPECT_EQ(sentinel_passive_calls.load(), int64_t{2} * kThreads * kRounds * kStepsPerData);
  EXPECT_EQ(sentinel_passive_calls_alone.load(), 0);
  EXPECT_GT(sentinel_filter_calls.load(), 0) << "the untagged box-floor pair skipped the sentinel";
  // the tagged ball rests on its law: MuJoCo made no constraint for it (its
  // points are listed outside the solver, for the viewer)
  const int ball = mj_name2id(m, mjOBJ_GEOM, "ball");
  for (mjData* d : data) {
    for (int c = 0; c < d->ncon; ++c) {
      if (d->contact[c].geom1 != ball && d->contact[c].geom2 != ball) continue;
      EXPECT_EQ(d->contact[c].exclude, 1);
      EXPECT_EQ(d->contact[c].efc_address, -1);
    }
  }
  mjcb_contactfilter = nullptr;
  mjcb_passive = nullptr;
}

TEST_F(ThreadTest, PlainDataSteppedWhileTheHooksComeAndGoIsLeftToMujoco) {
  // An mjData WITHOUT a ContactData stepped on one thread while this one
  // creates the first ContactData and destroys the last, over and over. The
  // hooks are MuJoCo's process-wide pointers, so MuJoCo runs ours for the
  // plain data too: they must chain to what was there before (MuJoCo's own
  // rule here) without racing with the registration (ThreadSanitizer saw the
  // saved callbacks read without the registry's lock, fixed in 600ddcf).
  // MuJoCo's own unsynchronized reads of mjcb_* are not instrumented, so
  // TSan cannot see those. The plain data must end bit for bit where MuJoCo
  // alone takes it.
  constexpr int kPlainSteps = 20000;
  constexpr int kTogglesMidRun = 20;
  const ContactModel& laws = InlineLaws(
      testing::DropXml("law=hertz stiffness=1e7", 1.0, "Euler", 1e-4, true), "plain.xml");
  const mjModel* m = laws.model();
  mjData* reference = MakeData(m);
  mjData* plain = MakeData(m);
  mjData* hooked = MakeData(m);
  for (mjData* d : {reference, plain, hooked}) mj_resetDataKeyframe(m, d, 0);
  for (int i = 0; i < kPlainSteps; ++i) mj_step(m, reference);

  Barrier barrier(2);
  std::atomic<int> plain_steps{0};
  std::atomic<int> toggles{0};
  std::thread stepper([&] {
    barrier.Wait();
    for (int i = 0; i < kPlainSteps; ++i) {
      // halfway, wait for the other thread to have come and gone a few times
      if (i == kPlainSteps / 2) {
        while (toggles.load() < kTogglesMidRun) std::this_thread::yield();
      }
      mj_step(m, plain);
      plain_steps.store(i + 1);
    }
  });
  barrier.Wait();
  while (plain_steps.load() < kPlainSteps) {
    ContactData contacts(laws, hooked);
    contacts.Step();
    toggles.fetch_add(1);
  }
  stepper.join();

  EXPECT_GE(toggles.load(), kTogglesMidRun);
  EXPECT_EQ(std::memcmp(reference->qpos, plain->qpos, sizeof(mjtNum) * m->nq), 0);
  EXPECT_EQ(std::memcmp(reference->qvel, plain->qvel, sizeof(mjtNum) * m->nv), 0);
  EXPECT_GT(reference->ncon, 0) << "the plain ball must rest on MuJoCo's own contact";
  EXPECT_EQ(mjcb_contactfilter, nullptr);
  EXPECT_EQ(mjcb_passive, nullptr);
}

}  // namespace
}  // namespace contactlaws
