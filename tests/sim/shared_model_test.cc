// Copyright contactlaws authors.
//
// One model, many data: eight Simulations of one Scene share its const
// mjModel, each with tag overrides, a timestep or integrator of its own, half
// of them with the auto timestep. Stepped on four threads at once, each gives
// bit for bit what it gives alone, and the shared model is never written.
// Built under ThreadSanitizer too (scripts/test.sh tsan).

#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "contactlaws/contactlaws.h"
#include "mujoco/thread_test_util.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

using testing::Barrier;
using testing::RunResult;
using testing::Same;

// s: the ball touches within 5e-5 s and leaves about 1.2 ms later
constexpr double kDuration = 3e-3;
constexpr double kSampleRate = 1e4;  // rows per simulated second
constexpr int kThreads = 4;

// One run: its options and, for the auto timestep, its options.
struct Case {
  SimulationOptions options;
  std::optional<AutoTimestepOptions> auto_timestep;
};

Case Make(const char* law, double e, std::optional<double> timestep = std::nullopt,
          std::optional<int> integrator = std::nullopt,
          std::optional<AutoTimestepOptions> auto_timestep = std::nullopt) {
  Case c;
  c.options.overrides.law = *ParseLawName(law);
  c.options.overrides.restitution = e;
  c.options.timestep = timestep;
  c.options.integrator = integrator;
  c.auto_timestep = auto_timestep;
  return c;
}

// Eight runs of the scene: laws, restitutions, timesteps, integrators, and
// four auto timesteps (one with a cap on its steps, one at 1e-4).
std::vector<Case> Cases() {
  AutoTimestepOptions fine;
  fine.accuracy = 1e-4;
  AutoTimestepOptions capped;
  capped.max_step = 1e-4;
  return {
      Make("flores", 0.5),
      Make("hunt-crossley", 0.9, std::nullopt, std::nullopt, AutoTimestepOptions{}),
      Make("kelvin-voigt", 0.7, 2e-5, mjINT_EULER),
      Make("lankarani-nikravesh", 0.3, std::nullopt, std::nullopt, fine),
      Make("hertz", 1.0, std::nullopt, mjINT_IMPLICIT),
      Make("exact", 0.6, std::nullopt, mjINT_EULER, AutoTimestepOptions{}),
      Make("flores", 0.8, 5e-6),
      Make("gonthier", 0.4, std::nullopt, std::nullopt, capped),
  };
}

// What a run leaves: its rows, its final state and impacts.
struct Outcome {
  std::vector<double> rows;
  RunResult end;
  AdvanceResult::Status status = AdvanceResult::Status::kDiverged;
  const mjModel* shared = nullptr;  // the model its data was stepped with
};

Outcome RunCase(const Scene& scene, const Case& c, Barrier* start = nullptr) {
  Outcome out;
  std::unique_ptr<Simulation> sim = scene.Make(c.options);
  out.shared = sim->shared_model().get();
  AdvanceOptions advance;
  advance.duration = kDuration;
  advance.sample_rate = kSampleRate;
  advance.auto_timestep = c.auto_timestep;
  if (start) start->Wait();
  out.status = Advance(sim.get(), advance, [&](const std::vector<double>& row) {
                 out.rows.insert(out.rows.end(), row.begin(), row.end());
               }).status;
  const mjModel* m = sim->model();
  const mjData* d = sim->data();
  out.end.time = d->time;
  out.end.qpos.assign(d->qpos, d->qpos + m->nq);
  out.end.qvel.assign(d->qvel, d->qvel + m->nv);
  out.end.qacc.assign(d->qacc, d->qacc + m->nv);
  out.end.qfrc_passive.assign(d->qfrc_passive, d->qfrc_passive + m->nv);
  out.end.impacts = sim->contacts().impacts();
  out.end.elastic = sim->contacts().ElasticEnergy();
  out.end.dissipated = sim->contacts().DissipatedEnergy();
  return out;
}

TEST(SharedModelTest, EightDataOfOneModelOnFourThreadsGiveWhatEachGivesAlone) {
  const std::string xml = testing::DropXml(
      "law=flores restitution=0.5 stiffness=1.4e8 linear_stiffness=5e6", 2.0, "RK4", 1e-5,
      /*gravity=*/true);
  const Scene scene("shared.xml", LoadModelString(xml, "shared.xml"));
  // the model's header and option, to hold against it after the runs
  const mjModel before = *scene.model();
  const std::vector<Case> cases = Cases();
  const int n = static_cast<int>(cases.size());

  std::vector<Outcome> alone;
  for (const Case& c : cases) alone.push_back(RunCase(scene, c));

  // case k on thread k % kThreads, all threads released at once
  std::vector<Outcome> together(n);
  Barrier start(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int k = t; k < n; k += kThreads) {
        together[k] = RunCase(scene, cases[k], k < kThreads ? &start : nullptr);
      }
    });
  }
  for (std::thread& thread : threads) thread.join();

  for (int k = 0; k < n; ++k) {
    SCOPED_TRACE(::testing::Message() << "case " << k << ": "
                                      << LawName(*cases[k].options.overrides.law));
    EXPECT_EQ(alone[k].shared, scene.model()) << "a copy, not the shared model";
    ASSERT_EQ(alone[k].status, AdvanceResult::Status::kComplete);
    EXPECT_EQ(together[k].status, AdvanceResult::Status::kComplete);
    EXPECT_TRUE(Same(alone[k].end, together[k].end));
    ASSERT_EQ(alone[k].rows.size(), together[k].rows.size());
    EXPECT_EQ(std::memcmp(alone[k].rows.data(), together[k].rows.data(),
                          sizeof(double) * alone[k].rows.size()),
              0)
        << "rows differ";
    // each run bounced: there is an impact to compare
    ASSERT_FALSE(alone[k].end.impacts.empty());
    EXPECT_FALSE(alone[k].end.impacts[0].open);
  }
  // nothing wrote the model: its timestep, integrator, arena sizes
  EXPECT_EQ(std::memcmp(&before, scene.model(), sizeof(mjModel)), 0);
}

}  // namespace
}  // namespace contactlaws
