// Copyright contactlaws authors.
//
// auto_cost: issue 22's costs of the contact-aware step, as ratios of CPU
// time from one run (scripts/bench.sh prints them; no timed test holds them).
//
//   auto_cost [--short] [ITEM...]   the goals below (ITEM: 1, 1b, 1c; all by
//                                   default), with the runs' energy drifts;
//                                   --short: a tenth of each duration
//   auto_cost write DIR        the scenes as files (for the command line)
//
// Goals (CPU time of this thread):
//   1   49 balls dropped 2 s, ball-ball untagged / the same tagged  <= 1.5
//   1b  49 balls, ball-ball masked, 20 s at --accuracy 1e-5, rows at
//       1000 per second / no rows                                   <= 1.3
//   1c  the 666 pile, 0.1 s under auto / at a fixed 3e-5 s          <= 1.5

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "auto_scenes.h"
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
  out.steps = result.steps;
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

int Goals(double scale, const std::vector<std::string>& items) {
  auto wanted = [&](const char* item) {
    return items.empty() || std::find(items.begin(), items.end(), item) != items.end();
  };
  if (wanted("1")) Drop(scale);
  if (wanted("1b")) Rows(scale);
  if (wanted("1c")) Pile(scale);
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

int Write(const std::string& dir) {
  const std::pair<std::string, std::string> files[] = {
      {"drop_untagged.xml", BallDropXml(BallBallPairs::kUntagged)},
      {"drop_tagged.xml", BallDropXml(BallBallPairs::kTagged)},
      {"drop_masked.xml", BallDropXml(BallBallPairs::kMasked)},
      {"pile_216.xml", PileXml()}};
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
  fmt::print(stderr, "usage: auto_cost [--short] [1|1b|1c]... | auto_cost write DIR\n");
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
        if (item != "1" && item != "1b" && item != "1c") return Usage();
      }
      return contactlaws::bench::Goals(short_runs ? 0.1 : 1.0, items);
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "auto_cost: {}\n", e.what());
    return 1;
  }
  return Usage();
}
