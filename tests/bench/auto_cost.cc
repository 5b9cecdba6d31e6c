// Copyright contactlaws authors.
//
// auto_cost: issues 22's and 34's costs of the contact-aware step, as ratios of CPU
// time from one run (bench/bench.sh prints them; no timed test holds them).
//
//   auto_cost [--short] [ITEM...]   the goals below (ITEM: 1, 1b, 1c, 7; all
//                                   by default), with the runs' energy drifts;
//                                   --short: a tenth of each duration, item 7
//                                   run once
//   auto_cost write DIR        the scenes as files (for the command line)
//
// Goals (CPU time of this thread):
//   1   49 balls dropped 2 s, ball-ball untagged / the same tagged  <= 1.5
//   1b  49 balls, ball-ball masked, 20 s at --accuracy 1e-5, rows at
//       1000 per second / no rows                                   <= 1.3
//   1c  the 666 pile, 0.1 s under auto / at a fixed 3e-5 s          <= 1.5
//   7   issue 34: auto at 1e-3 / a fixed step as fine as the finest step
//       it asked for (AdvanceResult::finest_step), medians of 3 runs
//       alternated, on the 64 balls in a box (mjcf/ball_box_64.xml) 0.1 s,
//       the 666 pile 0.1 s and the 49 balls tagged 2 s           <= 1.5

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "auto_scenes.h"
#include "ball_box.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::bench {
namespace {

double ThreadSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

struct Measured {
  double cpu = 0;           // s
  double energy_drift = 0;  // J: the ledger's total at the end minus at the start
  double energy_scale = 0;  // J: |total| at the start
  long steps = 0;
  long rows = 0;
  double finest_step = 0;  // s, AdvanceResult::finest_step under auto
};

// Runs xml for duration s: auto at accuracy (fixed_step 0) or at fixed_step,
// with rows at sample_rate (0: none) handed to a sink that keeps the last.
Measured Run(const std::string& xml, const std::string& name, double duration,
             double accuracy, double fixed_step, double sample_rate) {
  const Scene scene(name, LoadModelString(xml, name));
  SimulationOptions options;
  if (fixed_step > 0) options.timestep = fixed_step;
  std::unique_ptr<Simulation> sim = scene.Make(options);
  AdvanceOptions advance;
  advance.duration = duration;
  advance.sample_rate = sample_rate;
  if (fixed_step == 0) advance.auto_timestep = AutoTimestepOptions{accuracy};
  Measured out;
  mj_forward(sim->model(), sim->data());
  const double start = sim->Energy().total();
  std::vector<double> last;
  const double t0 = ThreadSeconds();
  const AdvanceResult result = Advance(sim.get(), advance, [&](const std::vector<double>& row) {
    last = row;
    ++out.rows;
  });
  out.cpu = ThreadSeconds() - t0;
  if (result.status != AdvanceResult::Status::kComplete) {
    throw Error(fmt::format("{}: the run did not complete", name));
  }
  mj_forward(sim->model(), sim->data());
  out.energy_drift = sim->Energy().total() - start;
  out.energy_scale = std::abs(start);
  out.steps = fixed_step > 0 ? std::lround(duration / fixed_step) : result.steps;
  out.finest_step = result.finest_step;
  return out;
}

void Print(const char* what, const Measured& m) {
  fmt::print("  {:<44} {:8.3f} s CPU, {:8} steps, {:6} rows, energy drift {:.3g} of {:.4g} J\n",
             what, m.cpu, m.steps, m.rows, m.energy_drift, m.energy_scale);
}

void Ratio(const char* what, double ratio, double goal) {
  fmt::print("  {}: {:.3f} (goal <= {}: {})\n", what, ratio, goal,
             ratio <= goal ? "met" : "NOT met");
}

void Drop(double scale);
void Rows(double scale);
void Pile(double scale);
void AgainstFinest(bool short_runs);

int Goals(double scale, const std::vector<std::string>& items) {
  auto wanted = [&](const char* item) {
    return items.empty() || std::find(items.begin(), items.end(), item) != items.end();
  };
  if (wanted("1")) Drop(scale);
  if (wanted("1b")) Rows(scale);
  if (wanted("1c")) Pile(scale);
  if (wanted("7")) AgainstFinest(scale < 1);
  return 0;
}

void Drop(double scale) {
  fmt::print("issue 22, item 1: 49 balls dropped, {:g} s, auto at 1e-3, no rows\n", 2 * scale);
  const Measured untagged = Run(BallDropXml(BallBallPairs::kUntagged), "drop_untagged.xml",
                                2 * scale, 1e-3, 0, 0);
  const Measured tagged =
      Run(BallDropXml(BallBallPairs::kTagged), "drop_tagged.xml", 2 * scale, 1e-3, 0, 0);
  Print("ball-ball untagged", untagged);
  Print("ball-ball tagged", tagged);
  Ratio("untagged / tagged", untagged.cpu / tagged.cpu, 1.5);
}

void Rows(double scale) {
  fmt::print("issue 22, item 1b: 49 balls, ball-ball masked, {:g} s, auto at 1e-5\n", 20 * scale);
  const std::string masked = BallDropXml(BallBallPairs::kMasked);
  const Measured quiet = Run(masked, "drop_masked.xml", 20 * scale, 1e-5, 0, 0);
  const Measured rows = Run(masked, "drop_masked.xml", 20 * scale, 1e-5, 0, 1000);
  Print("no rows", quiet);
  Print("1000 rows per second", rows);
  Ratio("rows / no rows", rows.cpu / quiet.cpu, 1.3);
}

void Pile(double scale) {
  fmt::print("issue 22, item 1c: the 666 pile, {:g} s, no rows\n", 0.1 * scale);
  const std::string pile = PileXml();
  const Measured automatic = Run(pile, "pile_216.xml", 0.1 * scale, 1e-3, 0, 0);
  const Measured fixed = Run(pile, "pile_216.xml", 0.1 * scale, 0, 3e-5, 0);
  Print("auto at 1e-3", automatic);
  Print("fixed 3e-5 s", fixed);
  Ratio("auto / fixed 3e-5 s", automatic.cpu / fixed.cpu, 1.5);
}

// The median of runs' CPU times.
double MedianCpu(std::vector<Measured> runs) {
  std::sort(runs.begin(), runs.end(),
            [](const Measured& a, const Measured& b) { return a.cpu < b.cpu; });
  return runs[runs.size() / 2].cpu;
}

// xml for duration s under auto at 1e-3, and at a fixed step as fine as the
// finest step the auto run asked for; runs times each, alternated.
void AutoAgainstItsFinest(const char* what, const std::string& xml, const std::string& name,
                          double duration, int runs) {
  std::vector<Measured> automatic, fixed;
  for (int i = 0; i < runs; ++i) {
    automatic.push_back(Run(xml, name, duration, 1e-3, 0, 0));
    if (!std::isfinite(automatic.back().finest_step)) {
      fmt::print("  {}, {:g} s: no contact came near\n", what, duration);
      return;
    }
    fixed.push_back(Run(xml, name, duration, 0, automatic.back().finest_step, 0));
  }
  fmt::print("  {}, {:g} s: finest auto step {:.4g} s\n", what, duration,
             automatic.back().finest_step);
  Print("auto at 1e-3", automatic.back());
  Print("fixed at the finest", fixed.back());
  Ratio("auto / fixed at its finest, CPU (median)", MedianCpu(automatic) / MedianCpu(fixed), 1.5);
}

void AgainstFinest(bool short_runs) {
  const int runs = short_runs ? 1 : 3;
  fmt::print("issue 34, items 6 and 7: auto against a fixed step as fine as its finest, "
             "no rows, {} run(s) each\n", runs);
  // --short: still past the first contacts (the pile lands at 0.045 s, the
  // drop at 1.0 s)
  AutoAgainstItsFinest("64 balls in a box", BallBoxXml(64), "ball_box_64.xml",
                       short_runs ? 0.01 : 0.1, runs);
  AutoAgainstItsFinest("the 666 pile", PileXml(), "pile_216.xml", short_runs ? 0.05 : 0.1, runs);
  AutoAgainstItsFinest("49 balls dropped, ball-ball tagged", BallDropXml(BallBallPairs::kTagged),
                       "drop_tagged.xml", short_runs ? 1.02 : 2, runs);
}

int Write(const std::string& dir) {
  const std::pair<std::string, std::string> files[] = {
      {"drop_untagged.xml", BallDropXml(BallBallPairs::kUntagged)},
      {"drop_tagged.xml", BallDropXml(BallBallPairs::kTagged)},
      {"drop_masked.xml", BallDropXml(BallBallPairs::kMasked)},
      {"pile_216.xml", PileXml()},
      {"ball_box_64.xml", BallBoxXml(64)}};
  for (const auto& [name, xml] : files) {
    const std::string path = dir + "/" + name;
    std::ofstream file(path, std::ios::binary);
    file << xml;
    if (!file) {
      fmt::print(stderr, "auto_cost: could not write {}\n", path);
      return 1;
    }
  }
  return 0;
}

}  // namespace
}  // namespace contactlaws::bench

int Usage() {
  fmt::print(stderr, "usage: auto_cost [--short] [1|1b|1c|7]... | auto_cost write DIR\n");
  return 2;
}

int main(int argc, char** argv) {
  try {
    const std::string first = argc > 1 ? argv[1] : "";
    if (argc == 3 && first == "write") return contactlaws::bench::Write(argv[2]);
    if (first != "write") {
      const bool short_runs = first == "--short";
      std::vector<std::string> items(argv + 1 + short_runs, argv + argc);
      for (const std::string& item : items) {
        if (item != "1" && item != "1b" && item != "1c" && item != "7") return Usage();
      }
      return contactlaws::bench::Goals(short_runs ? 0.1 : 1.0, items);
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "auto_cost: {}\n", e.what());
    return 1;
  }
  return Usage();
}
