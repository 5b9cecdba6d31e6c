// Copyright contactlaws authors.
//
// contactlaws: the command line.
//   contactlaws run SCENE [--law L] [--restitution E] [--duration T] ...
// Exit status: 0 done, 2 refused input (one line on stderr naming the file,
// tag, key and value), 1 anything else.

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/csv_file.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::cli {
namespace {

constexpr int kExitRefused = 2;

struct RunArgs {
  std::string scene;
  std::optional<std::string> law;
  std::optional<double> restitution;
  double duration = 2.0;
  std::optional<double> timestep;
  std::optional<std::string> integrator;
  double sample_rate = 1000.0;
  std::optional<std::string> output;
  std::optional<std::string> impacts;
};

[[noreturn]] void Refuse(const std::string& option, const std::string& value,
                         const std::string& requirement) {
  throw Error(fmt::format("{}={} {}", option, value, requirement));
}

void RequirePositive(const char* option, double value, const char* unit) {
  if (!(std::isfinite(value) && value > 0)) {
    Refuse(option, fmt::format("{}", value), fmt::format("must be a number > 0 ({})", unit));
  }
}

// The simulation options the flags ask for, validated.
SimulationOptions ParseSimulationOptions(const RunArgs& a) {
  SimulationOptions options;
  if (a.law) {
    options.overrides.law = ParseLawName(*a.law);
    if (!options.overrides.law) {
      Refuse("--law", *a.law,
             "is not a law (hertz, kelvin-voigt, hunt-crossley, lankarani-nikravesh, flores)");
    }
  }
  if (a.restitution) {
    if (!(std::isfinite(*a.restitution) && *a.restitution >= 0 && *a.restitution <= 1)) {
      Refuse("--restitution", fmt::format("{}", *a.restitution), "must be in [0, 1]");
    }
    options.overrides.restitution = a.restitution;
  }
  RequirePositive("--duration", a.duration, "s");
  RequirePositive("--sample-rate", a.sample_rate, "rows per simulated second");
  if (a.timestep) {
    RequirePositive("--timestep", *a.timestep, "s");
    options.timestep = a.timestep;
  }
  if (a.integrator) {
    if (*a.integrator == "euler") {
      options.integrator = mjINT_EULER;
    } else if (*a.integrator == "rk4") {
      options.integrator = mjINT_RK4;
    } else if (*a.integrator == "implicit") {
      options.integrator = mjINT_IMPLICIT;
    } else {
      Refuse("--integrator", *a.integrator, "must be euler, rk4 or implicit");
    }
  }
  return options;
}

// Empty for a value that does not exist (an episode still open).
std::string Number(double v) { return fmt::format("{}", v); }

void WriteImpacts(const Simulation& sim, CsvFile* file) {
  const ContactModel& cm = sim.contact_model();
  file->Header({"law", "restitution", "pair", "geom1", "geom2", "index", "time_contact",
                "time_separation", "impact_velocity", "separation_velocity",
                "restitution_post", "max_depth", "max_force"});
  for (const Impact& impact : sim.contacts().impacts()) {
    const PairTag& tag = cm.tags()[impact.tag];
    const GeomPair& pair = cm.pairs()[impact.pair];
    const bool closed = !impact.open;
    file->Fields({std::string(LawName(tag.law)), Number(pair.params.restitution), tag.label,
                  ObjectName(sim.model(), mjOBJ_GEOM, pair.named[0]),
                  ObjectName(sim.model(), mjOBJ_GEOM, pair.named[1]),
                  Number(impact.index), Number(impact.time_contact),
                  closed ? Number(impact.time_separation) : "",
                  Number(impact.impact_velocity),
                  closed ? Number(impact.separation_velocity) : "",
                  closed ? Number(impact.restitution_post()) : "", Number(impact.max_depth),
                  Number(impact.max_force)});
  }
}

void PrintSummary(const Simulation& sim, std::FILE* out) {
  const ContactModel& cm = sim.contact_model();
  fmt::print(out, "{:<20} {:<20} {:>11} {:>8} {:>14} {:>14}\n", "pair", "law", "restitution",
             "impacts", "first e_post", "max force (N)");
  for (int t = 0; t < static_cast<int>(cm.tags().size()); ++t) {
    const PairTag& tag = cm.tags()[t];
    int count = 0;
    std::optional<double> first_post;
    double max_force = 0;
    for (const Impact& impact : sim.contacts().impacts()) {
      if (impact.tag != t) continue;
      ++count;
      if (!first_post && !impact.open) first_post = impact.restitution_post();
      max_force = std::max(max_force, impact.max_force);
    }
    fmt::print(out, "{:<20} {:<20} {:>11} {:>8} {:>14} {:>14.6g}\n", tag.label,
               LawName(tag.law), tag.law == LawKind::kHertz ? "-" : Number(tag.restitution),
               count, first_post ? fmt::format("{:.6f}", *first_post) : "-", max_force);
  }
}

int Run(const RunArgs& args) {
  const SimulationOptions options = ParseSimulationOptions(args);
  Simulation sim(LoadModelFile(args.scene), args.scene, options);

  // open the outputs before the run: an unwritable path fails now
  std::optional<CsvFile> trajectory;
  std::optional<CsvFile> impacts;
  if (args.output) trajectory.emplace(*args.output);
  if (args.impacts) impacts.emplace(*args.impacts);

  const double dt = sim.model()->opt.timestep;
  const double period = 1.0 / args.sample_rate;
  std::vector<double> row;
  if (trajectory) trajectory->Header(sim.Columns());

  // step to the end, sampling on the grid k * period
  long next_sample = 0;
  auto sample_if_due = [&] {
    if (trajectory && sim.time() >= next_sample * period - 0.5 * dt) {
      sim.Sample(&row);
      trajectory->Row(row);
      while (next_sample * period - 0.5 * dt <= sim.time()) ++next_sample;
    }
  };
  sample_if_due();
  while (sim.time() < args.duration - 0.5 * dt) {
    sim.Step();
    sample_if_due();
  }

  if (trajectory) trajectory->Commit();
  if (impacts) {
    WriteImpacts(sim, &*impacts);
    impacts->Commit();
  }
  PrintSummary(sim, args.output && *args.output == "-" ? stderr : stdout);
  return 0;
}

// contactlaws laws: every law with its formula, parameters and citation.
int PrintLaws() {
  fmt::print("Convention: depth d > 0 in contact (m), depth rate d' > 0 approaching (m/s),\n"
             "v0 = d' at first touch (m/s, floored by min_impact_velocity, default {} m/s),\n"
             "force F >= 0 pushes apart (N); F = 0 for d <= 0; clamped to F >= 0 unless\n"
             "allow_tension=true.\n",
             kDefaultMinImpactVelocity);
  for (LawKind kind : kAllLaws) {
    fmt::print("\n{}\n  {}\n  parameters: {}\n  reference:  {}\n", LawName(kind),
               LawFormula(kind), LawParameters(kind), LawReference(kind));
  }
  return 0;
}

int Main(int argc, char** argv) {
  CLI::App app{"contactlaws: continuous contact force laws (Flores et al. 2011) in MuJoCo 2.2",
               "contactlaws"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help for every command");

  RunArgs run;
  CLI::App* run_cmd = app.add_subcommand("run", "simulate one tagged scene");
  run_cmd->add_option("scene", run.scene, "MJCF scene with contactlaw tags")->required();
  run_cmd->add_option("--law", run.law,
                      "override every tagged pair's law: hertz, kelvin-voigt, "
                      "hunt-crossley, lankarani-nikravesh, flores");
  run_cmd->add_option("--restitution", run.restitution,
                      "override every tagged pair's restitution e, in [0, 1]");
  run_cmd->add_option("--duration", run.duration, "simulated time, s")->capture_default_str();
  run_cmd->add_option("--timestep", run.timestep, "s (default: the scene's)");
  run_cmd->add_option("--integrator", run.integrator, "euler, rk4 or implicit (default: the scene's)");
  run_cmd->add_option("--sample-rate", run.sample_rate, "trajectory rows per simulated second")
      ->capture_default_str();
  run_cmd->add_option("--output", run.output, "trajectory CSV ('-' for stdout); none if absent");
  run_cmd->add_option("--impacts", run.impacts, "impact log CSV, one row per contact episode");

  CLI::App* laws_cmd =
      app.add_subcommand("laws", "list the laws: formula, parameters, units, citation");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::string message = e.what();
    for (char& c : message) {
      if (c == '\n') c = ' ';
    }
    fmt::print(stderr, "contactlaws: {}\n", message);
    return kExitRefused;
  }

  try {
    if (run_cmd->parsed()) return Run(run);
    if (laws_cmd->parsed()) return PrintLaws();
  } catch (const Error& e) {
    fmt::print(stderr, "contactlaws: {}\n", e.what());
    return kExitRefused;
  } catch (const std::exception& e) {
    fmt::print(stderr, "contactlaws: internal error: {}\n", e.what());
    return 1;
  }
  return 1;
}

}  // namespace
}  // namespace contactlaws::cli

int main(int argc, char** argv) { return contactlaws::cli::Main(argc, argv); }
