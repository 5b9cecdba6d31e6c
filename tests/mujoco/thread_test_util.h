// Copyright contactlaws authors.
//
// Runs of tagged scenes on threads, compared bit for bit with runs one after
// the other: for threads_test.cc and hooks_test.cc.
//
// Every concurrent run starts behind a spin barrier and meets the others
// again at its halfway step, so each run overlaps every other whatever the
// scheduler does.

#ifndef CONTACTLAWS_TESTS_MUJOCO_THREAD_TEST_UTIL_H_
#define CONTACTLAWS_TESTS_MUJOCO_THREAD_TEST_UTIL_H_

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

namespace contactlaws::testing {

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
  std::vector<Episode> impacts;
  double elastic = 0;
  double dissipated = 0;
};

// One run: steps a ContactData of (laws, d) from d's current state; with
// midway, waits there at the halfway step for the other threads' runs.
inline RunResult RunScene(const ContactModel& laws, mjData* d, int steps, Barrier* midway = nullptr) {
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

// Bit for bit: memcmp of the arrays, and each double of each Episode as bits
// (so -0.0 against 0.0 and NaN against NaN count as they are stored).
inline bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

inline bool SameArray(const std::vector<mjtNum>& a, const std::vector<mjtNum>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(mjtNum) * a.size()) == 0;
}

inline ::testing::AssertionResult Same(const RunResult& a, const RunResult& b) {
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
    const Episode& x = a.impacts[i];
    const Episode& y = b.impacts[i];
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

inline void SetInitialState(const Job& job, mjData* d) {
  const mjModel* m = job.laws->model();
  if (m->nkey > 0) {
    mj_resetDataKeyframe(m, d, 0);
  } else {
    mj_resetData(m, d);
  }
  if (!std::isnan(job.height)) d->qpos[2] = job.height;
  if (!std::isnan(job.velocity)) d->qvel[2] = job.velocity;
}

class ThreadTest : public MujocoTest {
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

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_MUJOCO_THREAD_TEST_UTIL_H_
