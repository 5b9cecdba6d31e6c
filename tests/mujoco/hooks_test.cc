// Copyright contactlaws authors.
//
// Threads: several models, and several mjData of one model, stepped
// concurrently give bit for bit what they give one after the other; the
// callbacks found before ours are chained while ours are installed and
// restored when the last ContactData goes, whatever thread creates and
// destroys them.
//
// Every concurrent run starts behind a spin barrier and meets the others
// again at its halfway step, so each run overlaps every other whatever the
// scheduler does, and the comparison is shown to see a difference of one
// part in 1e9 in a speed.

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

// A spin barrier: every thread leaves Wait() only once all have arrived
// (std::latch is C++20).
class Barrier {
 public:
  explicit Barrier(int count) : remaining_(count) {}
  void Wait() {
    remaining_.fetch_sub(1, std::memory_order_acq_rel);
    while (remaining_.load(std::memory_order_acquire) > 0) std::this_thread::yield();
  }

 private:
  std::atomic<int> remaining_;
};

// What a run leaves: the state, every impact, the energy ledger.
struct RunResult {
  double time = 0;
  std::vector<mjtNum> qpos, qvel, qacc, qfrc_passive;
  std::vector<Impact> impacts;
  double elastic = 0;
  double dissipated = 0;
};

// One run: steps a ContactData of (laws, d) from d's current state; with
// midway, waits there at the halfway step for the other threads' runs.
RunResult RunScene(const ContactModel& laws, mjData* d, int steps, Barrier* midway = nullptr) {
  const mjModel* m = laws.model();
  ContactData contacts(laws, d);
  for (int i = 0; i < steps; ++i) {
    if (midway && i == steps / 2) midway->Wait();
    contacts.Step();
  }
  RunResult r;
  r.time = d->time;
  r.qpos.assign(d->qpos, d->qpos + m->nq);
  r.qvel.assign(d->qvel, d->qvel + m->nv);
  r.qacc.assign(d->qacc, d->qacc + m->nv);
  r.qfrc_passive.assign(d->qfrc_passive, d->qfrc_passive + m->nv);
  r.impacts = contacts.impacts();
  r.elastic = contacts.ElasticEnergy();
  r.dissipated = contacts.DissipatedEnergy();
  return r;
}

// Bit for bit: memcmp of the arrays, and each double of each Impact as bits
// (so -0.0 against 0.0 and NaN against NaN count as they are stored).
bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

bool SameArray(const std::vector<mjtNum>& a, const std::vector<mjtNum>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(mjtNum) * a.size()) == 0;
}

::testing::AssertionResult Same(const RunResult& a, const RunResult& b) {
  auto fail = [](const std::string& what) {
    return ::testing::AssertionFailure() << what << " differs";
  };
  if (!SameBits(a.time, b.time)) return fail("time");
  if (!SameArray(a.qpos, b.qpos)) return fail("qpos");
  if (!SameArray(a.qvel, b.qvel)) return fail("qvel");
  if (!SameArray(a.qacc, b.qacc)) return fail("qacc");
  if (!SameArray(a.qfrc_passive, b.qfrc_passive)) return fail("qfrc_passive");
  if (!SameBits(a.elastic, b.elastic)) return fail("elastic energy");
  if (!SameBits(a.dissipated, b.dissipated)) return fail("dissipated energy");
  if (a.impacts.size() != b.impacts.size()) {
    return ::testing::AssertionFailure()
           << "impact count differs: " << a.impacts.size() << " vs " << b.impacts.size();
  }
  for (size_t i = 0; i < a.impacts.size(); ++i) {
    const Impact& x = a.impacts[i];
    const Impact& y = b.impacts[i];
    const std::string at = "impact " + std::to_string(i) + ": ";
    if (x.tag != y.tag) return fail(at + "tag");
    if (x.pair != y.pair) return fail(at + "pair");
    if (x.index != y.index) return fail(at + "index");
    if (x.open != y.open) return fail(at + "open");
    if (!SameBits(x.time_contact, y.time_contact)) return fail(at + "time_contact");
    if (!SameBits(x.impact_velocity, y.impact_velocity)) return fail(at + "impact_velocity");
    if (!SameBits(x.time_separation, y.time_separation)) return fail(at + "time_separation");
    if (!SameBits(x.separation_velocity, y.separation_velocity)) {
      return fail(at + "separation_velocity");
    }
    if (!SameBits(x.max_depth, y.max_depth)) return fail(at + "max_depth");
    if (!SameBits(x.max_force, y.max_force)) return fail(at + "max_force");
  }
  return ::testing::AssertionSuccess();
}

// One scene to run: its model and tags, and how to set its initial state.
struct Job {
  const ContactModel* laws = nullptr;
  // ball height (qpos[2]) and vertical speed (qvel[2], m/s); NaN: keyframe 0
  double height = std::numeric_limits<double>::quiet_NaN();
  double velocity = std::numeric_limits<double>::quiet_NaN();
};

void SetInitialState(const Job& job, mjData* d) {
  const mjModel* m = job.laws->model();
  if (m->nkey > 0) {
    mj_resetDataKeyframe(m, d, 0);
  } else {
    mj_resetData(m, d);
  }
  if (!std::isnan(job.height)) d->qpos[2] = job.height;
  if (!std::isnan(job.velocity)) d->qvel[2] = job.velocity;
}

class ThreadTest : public testing::MujocoTest {
 protected:
  // Each job in turn on this thread.
  std::vector<RunResult> RunOneByOne(const std::vector<Job>& jobs, int steps) {
    std::vector<RunResult> results;
    for (const Job& job : jobs) {
      mjData* d = MakeData(job.laws->model());
      SetInitialState(job, d);
      results.push_back(RunScene(*job.laws, d, steps));
    }
    return results;
  }

  // Every job on its own thread, all released at once and met again halfway.
  std::vector<RunResult> RunConcurrently(const std::vector<Job>& jobs, int steps) {
    const int n = static_cast<int>(jobs.size());
    std::vector<mjData*> data;
    for (const Job& job : jobs) {
      data.push_back(MakeData(job.laws->model()));
      SetInitialState(job, data.back());
    }
    std::vector<RunResult> results(n);
    Barrier start(n);
    Barrier midway(n);
    std::vector<std::thread> threads;
    for (int i = 0; i < n; ++i) {
      threads.emplace_back([&, i] {
        start.Wait();
        results[i] = RunScene(*jobs[i].laws, data[i], steps, &midway);
      });
    }
    for (std::thread& t : threads) t.join();
    return results;
  }

  const ContactModel& Laws(UniqueModel model, const std::string& name) {
    models_.push_back(std::move(model));
    laws_.push_back(std::make_unique<ContactModel>(models_.back().get(), name));
    return *laws_.back();
  }

  const ContactModel& InlineLaws(const std::string& xml, const std::string& name) {
    return Laws(LoadModelString(xml, name), name);
  }

  const ContactModel& SceneLaws(const std::string& file) {
    return Laws(LoadModelFile(std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/" + file), file);
  }

  // Several models: three drops (different laws, restitutions, speeds,
  // integrators) and the paper's two scenes, started just above contact.
  std::vector<Job> SeveralModels() {
    using testing::DropXml;
    return {
        Job{&InlineLaws(DropXml("law=flores restitution=0.5 stiffness=1.4e8", 3.0, "RK4", 1e-5,
                                true),
                        "flores.xml")},
        Job{&InlineLaws(DropXml("law=kelvin-voigt restitution=0.7 linear_stiffness=5e6", 2.0,
                                "Euler", 1e-5, true, 2.0),
                        "kelvin-voigt.xml")},
        Job{&InlineLaws(DropXml("law=hunt-crossley restitution=0.3 stiffness=1e9", 1.5,
                                "implicit", 2e-5),
                        "hunt-crossley.xml")},
        Job{&SceneLaws("bouncing_ball.xml"), 0.1002, -4.2},
        Job{&SceneLaws("ball_table.xml"), 0.6002, -4.2},
    };
  }

 private:
  std::vector<UniqueModel> models_;
  std::vector<std::unique_ptr<ContactModel>> laws_;
};

// Enough steps for every job's first contact to open and close (the
// paper's ball: about 130 steps of contact after 5 steps of flight), and
// for each thread to outlast a scheduler time slice (about 25 ms a run).
constexpr int kSteps = 10000;

TEST_F(ThreadTest, ModelsSteppedConcurrentlyGiveWhatTheyGiveOneByOne) {
  const std::vector<Job> jobs = SeveralModels();
  const std::vector<RunResult> alone = RunOneByOne(jobs, kSteps);
  const std::vector<RunResult> together = RunConcurrently(jobs, kSteps);
  for (size_t i = 0; i < jobs.size(); ++i) {
    SCOPED_TRACE(jobs[i].laws->source());
    EXPECT_TRUE(Same(alone[i], together[i]));
    // each run must have bounced, or there is nothing to compare
    ASSERT_FALSE(alone[i].impacts.empty());
    EXPECT_FALSE(alone[i].impacts[0].open);
  }
}

TEST_F(ThreadTest, DataOfOneModelSteppedConcurrentlyGiveWhatTheyGiveOneByOne) {
  // one ContactModel shared by four mjData, each at its own speed
  const ContactModel& laws = InlineLaws(
      testing::DropXml("law=lankarani-nikravesh restitution=0.6 stiffness=1.4e8", 3.0, "RK4"),
      "shared.xml");
  std::vector<Job> jobs;
  for (double speed : {1.0, 2.0, 3.0, 4.0}) jobs.push_back(Job{&laws, 0.1001, -speed});
  const std::vector<RunResult> alone = RunOneByOne(jobs, kSteps);
  const std::vector<RunResult> together = RunConcurrently(jobs, kSteps);
  for (size_t i = 0; i < jobs.size(); ++i) {
    SCOPED_TRACE(::testing::Message() << "speed " << -jobs[i].velocity);
    EXPECT_TRUE(Same(alone[i], together[i]));
    ASSERT_FALSE(alone[i].impacts.empty());
    EXPECT_FALSE(alone[i].impacts[0].open);
    // each data saw its own speed, not another's (gravity off: exact)
    EXPECT_DOUBLE_EQ(alone[i].impacts[0].impact_velocity, -jobs[i].velocity);
  }
}

TEST_F(ThreadTest, TheComparisonSeesOneThreadAtAnotherSpeed) {
  // the same concurrent run, with one thread's speed changed by 1e-9
  // relative: the comparison of the tests above must catch it, and only it
  const ContactModel& laws = InlineLaws(
      testing::DropXml("law=flores restitution=0.8 stiffness=1.4e8", 3.0, "RK4", 1e-5, true),
      "perturbed.xml");
  std::vector<Job> jobs;
  for (double speed : {1.0, 2.0, 3.0}) jobs.push_back(Job{&laws, 0.1002, -speed});
  const std::vector<RunResult> alone = RunOneByOne(jobs, kSteps);
  jobs[1].velocity *= 1 + 1e-9;
  const std::vector<RunResult> together = RunConcurrently(jobs, kSteps);
  EXPECT_TRUE(Same(alone[0], together[0]));
  EXPECT_FALSE(Same(alone[1], together[1]));
  EXPECT_TRUE(Same(alone[2], together[2]));
}

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
  // the tagged ball rests on its law: MuJoCo made no constraint for it
  const int ball = mj_name2id(m, mjOBJ_GEOM, "ball");
  for (mjData* d : data) {
    for (int c = 0; c < d->ncon; ++c) {
      EXPECT_NE(d->contact[c].geom1, ball);
      EXPECT_NE(d->contact[c].geom2, ball);
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
