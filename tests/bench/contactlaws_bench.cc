// Copyright contactlaws authors.
//
// contactlaws_bench: the benchmarks of issue 5 (Google Benchmark).
//
//   Law/<law>                      one EvaluateLaw call, ns, over varied states
//   BouncingBall/<variant>         mjcf/bouncing_ball.xml at its 1e-5 s, RK4, for a
//                                  fixed simulated stretch (3 s) per iteration:
//     hooks                        the contact laws (ContactData::Step)
//     mujoco                       MuJoCo's own soft contact: no ContactData alive,
//                                  the tags inert text
//     free_flight_hooks            the same model, gravity off, the ball rising at
//     free_flight_mujoco           1 m/s from 1 m: it never touches the floor
//   BallBox/<hooks|mujoco>/<n>     the many-ball scene (ball_box.h) of n = 8, 64, 512
//                                  balls, from its launch, a fixed stretch; hooks with
//                                  the tags' default friction (coulomb, mu = 1 from
//                                  the geoms), MuJoCo's own contact at condim 3
//   BallBox/hooks_frictionless/64  the same hooks with --friction none (issue 12's
//                                  cost of friction)
//   Sweep/fixed, Sweep/auto        the `restitution` command's runs (drop until the
//                                  first contact episode ends) for a subset of
//                                  (law, e), at the scene's fixed 1e-5 s
//
// Every stepping benchmark reports counters: `steps` per iteration and
// `per_step` (time per step, s), so that stretches of different lengths
// compare; bench/bench.sh turns one run's JSON into ratios.
//
// Own flag, before Google Benchmark's: --smoke shortens every stretch (ctest's
// smoke check; the numbers then mean nothing).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include "ball_box.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::bench {
namespace {

// The box whose cost of friction issue 12 bounds (mjcf/ball_box_64.xml).
constexpr int kFrictionBalls = 64;

// Simulated stretches per iteration (s); --smoke divides them.
struct Stretches {
  double bouncing_ball = 3.0;  // the goal: 3 s at 1e-5 s
  double ball_box = 0.01;      // from the launch: its impacts begin at 1-2 ms
  std::vector<int> ball_counts = {8, 64, 512};
  // the sweep's subset: every law at one e, until the first episode ends
  std::vector<LawId> sweep_laws = {AllLaws().begin(), AllLaws().end()};
  std::vector<double> sweep_restitutions = {0.5};
};

std::string ScenePath(const std::string& file) {
  return std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf/" + file;
}

void AddStepCounters(benchmark::State& state, long steps) {
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["per_step"] = benchmark::Counter(
      static_cast<double>(steps), benchmark::Counter::kIsIterationInvariantRate |
                                      benchmark::Counter::kInvert);
}

// Fails the benchmark on a MuJoCo warning: a benchmark of a broken run
// measures nothing.
bool CheckWarnings(benchmark::State& state, const mjData* d) {
  for (int i = 0; i < mjNWARNING; ++i) {
    if (d->warning[i].number > 0) {
      state.SkipWithError(fmt::format("MuJoCo warning {} raised", i).c_str());
      return false;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------
// Law kernels.

// The paper's ball: K = 1.4e8 N/m^1.5, n = 1.5, k = 5e6 N/m, e = 0.9.
LawParams PaperParams(LawId kind) {
  LawParams params;
  params.law = kind;
  params.restitution = 0.9;
  params.stiffness = 1.4e8;
  params.exponent = 1.5;
  params.linear_stiffness = 5e6;
  params.dissipation = 0.1;  // s/m, read by hunt-crossley-constant only
  ResolveLawParams(&params);
  return params;
}

constexpr double kPi = 3.14159265358979323846;

void BM_Law(benchmark::State& state, LawId kind) {
  const LawParams params = PaperParams(kind);
  // varied states of one contact (depth to 1.2 mm, approach and separation at
  // up to 4.4 m/s) so that no call is the same as the one before; the index
  // walks the table, which stays in L1
  constexpr int kStates = 256;
  std::array<ContactState, kStates> states;
  for (int i = 0; i < kStates; ++i) {
    const double phase = 2.0 * kPi * i / kStates;
    states[i].depth = 1.2e-3 * std::sin(0.5 * phase) + 1e-7;
    states[i].depth_rate = 4.4 * std::cos(0.5 * phase);
    states[i].impact_velocity = 4.4;
    states[i].effective_mass = 1.0;
  }
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(i);
    ContactForce force = EvaluateLaw(params, states[i]);
    benchmark::DoNotOptimize(force);
    i = (i + 1) % kStates;
  }
  state.SetItemsProcessed(state.iterations());
}

// ---------------------------------------------------------------------------
// The bouncing ball.

enum class Contact { kHooks, kHooksFrictionless, kMujoco };

struct BouncingBallCase {
  Contact contact;
  bool free_flight;
};

void BM_BouncingBall(benchmark::State& state, BouncingBallCase c, double duration) {
  const std::string path = ScenePath("bouncing_ball.xml");
  UniqueModel m = LoadModelFile(path);
  ContactModel laws(m.get(), path);
  if (c.free_flight) m->opt.gravity[2] = 0;  // and the ball rises, below
  UniqueData d(mj_makeData(m.get()));
  std::unique_ptr<ContactData> contacts;
  if (c.contact == Contact::kHooks) contacts = std::make_unique<ContactData>(laws, d.get());

  const long steps = std::lround(duration / m->opt.timestep);
  for (auto _ : state) {
    state.PauseTiming();
    mj_resetData(m.get(), d.get());
    if (c.free_flight) d->qvel[2] = 1.0;  // m/s, away from the floor
    if (contacts) contacts->Reset();
    state.ResumeTiming();
    if (contacts) {
      for (long k = 0; k < steps; ++k) contacts->Step();
    } else {
      for (long k = 0; k < steps; ++k) mj_step(m.get(), d.get());
    }
  }
  if (!CheckWarnings(state, d.get())) return;
  AddStepCounters(state, steps);
  // the ball's contacts over the stretch: none in free flight
  if (contacts) state.counters["episodes"] = static_cast<double>(contacts->impacts().size());
}

// ---------------------------------------------------------------------------
// The many-ball scene.

void BM_BallBox(benchmark::State& state, Contact contact, int balls, double duration) {
  const std::string name = fmt::format("ball_box_{}.xml", balls);
  UniqueModel m = LoadModelString(BallBoxXml(balls), name);
  Overrides overrides;
  if (contact == Contact::kHooksFrictionless) overrides.friction = FrictionKind::kNone;
  ContactModel laws(m.get(), name, overrides);
  UniqueData d(mj_makeData(m.get()));
  std::unique_ptr<ContactData> contacts;
  if (contact != Contact::kMujoco) contacts = std::make_unique<ContactData>(laws, d.get());

  // the launch, from the generator (the keyframe, where MuJoCo could read one,
  // holds the same numbers)
  const std::vector<double> launch = BallBoxLaunch(balls);
  if (m->nkey > 0 && !std::equal(launch.begin(), launch.end(), m->key_qvel)) {
    state.SkipWithError("the keyframe is not BallBoxLaunch");
    return;
  }

  const long steps = std::lround(duration / m->opt.timestep);
  long contact_points = 0;  // summed over the stretch's steps (last iteration)
  for (auto _ : state) {
    state.PauseTiming();
    mj_resetData(m.get(), d.get());
    std::copy(launch.begin(), launch.end(), d->qvel);
    if (contacts) contacts->Reset();
    contact_points = 0;
    state.ResumeTiming();
    if (contacts) {
      for (long k = 0; k < steps; ++k) contacts->Step();
    } else {
      for (long k = 0; k < steps; ++k) {
        mj_step(m.get(), d.get());
        contact_points += d->ncon;
      }
    }
  }
  if (!CheckWarnings(state, d.get())) return;
  AddStepCounters(state, steps);
  state.counters["balls"] = balls;
  if (contacts) {
    state.counters["episodes"] = static_cast<double>(contacts->impacts().size());
  } else {
    state.counters["mean_ncon"] = static_cast<double>(contact_points) / steps;
  }
}

// ---------------------------------------------------------------------------
// The restitution sweep: what `contactlaws restitution` runs for each
// (law, e), through the same Scene and Advance.

// The sweep with the scene's fixed 1e-5 s step, or with --timestep auto.
void BM_Sweep(benchmark::State& state, const Stretches& s, bool automatic) {
  const Scene scene(ScenePath("bouncing_ball.xml"));
  long steps = 0;
  for (auto _ : state) {
    steps = 0;
    for (LawId law : s.sweep_laws) {
      for (double e : s.sweep_restitutions) {
        SimulationOptions options;
        options.overrides.law = law;
        options.overrides.restitution = e;
        options.overrides.dissipation = 0.1;  // s/m, read by hunt-crossley-constant only
        std::unique_ptr<Simulation> sim = scene.Make(options);
        AdvanceOptions advance;
        advance.duration = 2.0;  // s: the first contact ends at ~0.45 s
        advance.until_first_episode = true;
        if (automatic) advance.auto_timestep = AutoTimestepOptions{};
        const AdvanceResult result = Advance(sim.get(), advance, nullptr);
        const std::vector<Episode>& impacts = sim->contacts().impacts();
        if (impacts.empty() || impacts[0].open) {
          state.SkipWithError("a first contact did not end within 2 s");
          return;
        }
        steps += automatic ? result.steps
                           : std::lround(sim->time() / sim->model()->opt.timestep);
      }
    }
  }
  const double runs = static_cast<double>(s.sweep_laws.size() * s.sweep_restitutions.size());
  state.counters["runs"] = runs;
  state.counters["per_run"] =
      benchmark::Counter(runs, benchmark::Counter::kIsIterationInvariantRate |
                                   benchmark::Counter::kInvert);
  AddStepCounters(state, steps);
}

void RegisterAll(const Stretches& s) {
  for (LawId kind : AllLaws()) {
    benchmark::RegisterBenchmark(fmt::format("Law/{}", LawName(kind)).c_str(), BM_Law, kind);
  }

  const std::pair<const char*, BouncingBallCase> bouncing[] = {
      {"hooks", {Contact::kHooks, false}},
      {"mujoco", {Contact::kMujoco, false}},
      {"free_flight_hooks", {Contact::kHooks, true}},
      {"free_flight_mujoco", {Contact::kMujoco, true}},
  };
  for (const auto& [name, c] : bouncing) {
    benchmark::RegisterBenchmark(fmt::format("BouncingBall/{}", name).c_str(), BM_BouncingBall,
                                 c, s.bouncing_ball)
        ->Unit(benchmark::kMillisecond);
  }

  for (int n : s.ball_counts) {
    for (Contact c : {Contact::kHooks, Contact::kMujoco}) {
      benchmark::RegisterBenchmark(
          fmt::format("BallBox/{}/{}", c == Contact::kHooks ? "hooks" : "mujoco", n).c_str(),
          BM_BallBox, c, n, s.ball_box)
          ->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::RegisterBenchmark(
      fmt::format("BallBox/hooks_frictionless/{}", kFrictionBalls).c_str(), BM_BallBox,
      Contact::kHooksFrictionless, kFrictionBalls, s.ball_box)
      ->Unit(benchmark::kMillisecond);

  benchmark::RegisterBenchmark("Sweep/fixed", BM_Sweep, s, false)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("Sweep/auto", BM_Sweep, s, true)->Unit(benchmark::kMillisecond);
}

}  // namespace
}  // namespace contactlaws::bench

int main(int argc, char** argv) {
  using contactlaws::bench::Stretches;
  Stretches stretches;
  // our own flag first; Google Benchmark reports whatever else it does not know
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--smoke") == 0) {
      stretches.bouncing_ball = 0.01;
      stretches.ball_box = 2e-4;
      stretches.sweep_laws = {*contactlaws::ParseLawName("hunt-crossley")};
    } else {
      args.push_back(argv[i]);
    }
  }
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
  contactlaws::bench::RegisterAll(stretches);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
