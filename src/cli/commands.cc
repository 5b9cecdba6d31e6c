// Copyright contactlaws authors.

#include "cli/commands.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/csv_file.h"
#include "cli/runner.h"
#include "contactlaws/estimate.h"
#include "contactlaws/summary.h"

namespace contactlaws::cli {
namespace {

// The restitution sweep of the paper's Fig. 7.
constexpr char kDefaultSweep[] = "0.1:1.0:0.1";

// One (law, restitution) combination of a sweep.
struct RunSpec {
  LawKind law = LawKind::kHertz;
  std::optional<double> restitution;  // nullopt: the scene's
};

std::string Describe(const RunSpec& spec) {
  return spec.restitution ? fmt::format("{} e={}", LawName(spec.law), *spec.restitution)
                          : std::string(LawName(spec.law));
}

SimulationOptions OptionsFor(SimulationOptions options, const RunSpec& spec) {
  options.overrides.law = spec.law;
  options.overrides.restitution = spec.restitution;
  return options;
}

// Progress lines on stderr, only when it is a terminal.
class Progress {
 public:
  Progress(int total, bool quiet) : total_(total), enabled_(!quiet && isatty(STDERR_FILENO)) {}
  ~Progress() { Done(); }
  // Ends the progress line, before anything else is printed.
  void Done() {
    if (enabled_ && started_) fmt::print(stderr, "\n");
    started_ = false;
  }
  void Start(int k, const std::string& what) {
    if (!enabled_) return;
    started_ = true;
    fmt::print(stderr, "\r\033[K[{}/{}] {}", k + 1, total_, what);
    std::fflush(stderr);
  }

 private:
  int total_;
  bool enabled_;
  bool started_ = false;
};

// Validates every run's tags before any is simulated: bad input costs nothing.
void ValidateAll(const Scene& scene, const SimulationOptions& options,
                 const std::vector<RunSpec>& specs) {
  for (const RunSpec& spec : specs) scene.Make(OptionsFor(options, spec));
}

// A table cell: "-" for a value that does not exist.
std::string Cell(const std::optional<double>& value, const char* format) {
  return value ? fmt::format(fmt::runtime(format), *value) : "-";
}

void PrintRunSummary(const Simulation& sim, std::FILE* out) {
  const ContactModel& cm = sim.contact_model();
  fmt::print(out, "{:<20} {:<20} {:>11} {:>8} {:>14} {:>14}\n", "pair", "law", "restitution",
             "impacts", "first e_post", "max force (N)");
  for (int t = 0; t < static_cast<int>(cm.tags().size()); ++t) {
    const PairTag& tag = cm.tags()[t];
    std::vector<Impact> impacts;
    for (const Impact& impact : sim.contacts().impacts()) {
      if (impact.tag == t) impacts.push_back(impact);
    }
    const RunSummary s = Summarize(impacts, sim.time());
    fmt::print(out, "{:<20} {:<20} {:>11} {:>8} {:>14} {:>14.6g}\n", tag.label,
               LawName(tag.law), tag.law == LawKind::kHertz ? "-" : Field(tag.restitution),
               s.impacts, Cell(s.restitution_post, "{:.6f}"), s.max_force);
  }
}


}  // namespace

int RunCommand(const RunArgs& args) {
  SimulationOptions options = ParseCommon(args);
  if (args.law) options.overrides.law = ParseLaw("--law", *args.law);
  if (args.restitution) {
    options.overrides.restitution = ParseRestitution("--restitution", *args.restitution);
  }
  const Scene scene(args.scene);
  std::unique_ptr<Simulation> sim = scene.Make(options);

  // open the outputs before the run: an unwritable path fails now
  std::optional<CsvFile> trajectory;
  std::optional<CsvFile> impacts;
  if (args.output) trajectory.emplace(*args.output);
  if (args.impacts) impacts.emplace(*args.impacts);

  if (trajectory) trajectory->Header(sim->Columns());
  AdvanceOptions advance{args.duration, trajectory ? args.sample_rate : 0.0, false};
  Advance(sim.get(), advance, [&](const std::vector<double>& row) { trajectory->Row(row); });

  if (trajectory) trajectory->Commit();
  if (impacts) {
    impacts->Header(ImpactColumns());
    for (const Impact& impact : sim->contacts().impacts()) {
      impacts->Fields(ImpactFields(*sim, impact));
    }
    impacts->Commit();
  }
  PrintRunSummary(*sim, args.output && *args.output == "-" ? stderr : stdout);
  return 0;
}

int CompareCommand(const SweepArgs& args) {
  const SimulationOptions options = ParseCommon(args);
  const std::vector<LawKind> laws = ParseLawList("--laws", args.laws);
  std::vector<double> restitutions;
  if (args.restitution) restitutions = ParseRestitutionList("--restitution", *args.restitution);

  // Hertz once; every other law at each restitution (the scene's if none given)
  std::vector<RunSpec> specs;
  for (LawKind law : laws) {
    if (law == LawKind::kHertz) {
      specs.push_back({law, 1.0});
    } else if (restitutions.empty()) {
      specs.push_back({law, std::nullopt});
    } else {
      for (double e : restitutions) specs.push_back({law, e});
    }
  }
  const Scene scene(args.scene);
  ValidateAll(scene, options, specs);

  std::error_code error;
  std::filesystem::create_directories(args.output_dir, error);
  if (error) {
    throw Error(fmt::format("{}: cannot create the output directory ({})", args.output_dir,
                            error.message()));
  }
  CsvFile trajectories(args.output_dir + "/trajectories.csv");
  CsvFile impacts(args.output_dir + "/impacts.csv");
  CsvFile summary(args.output_dir + "/summary.csv");
  impacts.Header(ImpactColumns());
  summary.Header({"law", "restitution", "impacts", "restitution_post", "max_depth",
                  "max_force", "contact_duration", "time_to_rest", "dissipated_energy"});

  struct Row {
    RunSpec spec;
    double restitution;
    RunSummary s;
    double dissipated;
  };
  std::vector<Row> rows;
  Progress progress(static_cast<int>(specs.size()), args.quiet);
  for (size_t k = 0; k < specs.size(); ++k) {
    const RunSpec& spec = specs[k];
    progress.Start(static_cast<int>(k), Describe(spec));
    std::unique_ptr<Simulation> sim = scene.Make(OptionsFor(options, spec));
    const PairTag& first_tag = sim->contact_model().tags().front();
    const double e = ReportedRestitution(spec.law, first_tag.restitution);
    if (k == 0) {
      std::vector<std::string> columns = {"law", "restitution"};
      for (std::string& c : sim->Columns()) columns.push_back(std::move(c));
      trajectories.Header(columns);
    }
    const std::vector<std::string> prefix = {std::string(LawName(spec.law)), Field(e)};
    Advance(sim.get(), {args.duration, args.sample_rate, false},
            [&](const std::vector<double>& row) { trajectories.Row(prefix, row); });
    for (const Impact& impact : sim->contacts().impacts()) {
      impacts.Fields(ImpactFields(*sim, impact));
    }
    const RunSummary s = Summarize(sim->contacts().impacts(), sim->time());
    const double dissipated = sim->contacts().DissipatedEnergy();
    summary.Fields({std::string(LawName(spec.law)), Field(e), Field(s.impacts),
                    Field(s.restitution_post), Field(s.max_depth), Field(s.max_force),
                    Field(s.contact_duration), Field(s.time_to_rest), Field(dissipated)});
    rows.push_back({spec, e, s, dissipated});
  }
  progress.Done();
  trajectories.Commit();
  impacts.Commit();
  summary.Commit();

  fmt::print("{:<20} {:>11} {:>8} {:>12} {:>14} {:>14} {:>13} {:>13} {:>15}\n", "law",
             "restitution", "impacts", "first e_post", "max depth (m)", "max force (N)",
             "duration (s)", "at rest (s)", "dissipated (J)");
  for (const Row& r : rows) {
    fmt::print("{:<20} {:>11} {:>8} {:>12} {:>14.6g} {:>14.6g} {:>13} {:>13} {:>15.6g}\n",
               LawName(r.spec.law), Field(r.restitution), r.s.impacts,
               Cell(r.s.restitution_post, "{:.6f}"), r.s.max_depth, r.s.max_force,
               Cell(r.s.contact_duration, "{:.6g}"), Cell(r.s.time_to_rest, "{:.6g}"),
               r.dissipated);
  }
  fmt::print("wrote {0}/trajectories.csv, {0}/impacts.csv, {0}/summary.csv\n", args.output_dir);
  return 0;
}

int RestitutionCommand(const SweepArgs& args) {
  const SimulationOptions options = ParseCommon(args);
  const std::vector<LawKind> laws = ParseLawList("--laws", args.laws);
  const std::vector<double> restitutions =
      ParseRestitutionList("--restitution", args.restitution.value_or(kDefaultSweep));
  std::vector<RunSpec> specs;
  for (LawKind law : laws) {
    for (double e : restitutions) specs.push_back({law, e});
  }
  const Scene scene(args.scene);
  ValidateAll(scene, options, specs);

  CsvFile out(args.output);
  out.Header({"law", "restitution", "restitution_post", "impact_velocity", "max_depth",
              "max_force", "contact_duration"});
  struct Row {
    RunSpec spec;
    std::optional<Impact> first;
  };
  std::vector<Row> rows;
  int incomplete = 0;
  Progress progress(static_cast<int>(specs.size()), args.quiet);
  for (size_t k = 0; k < specs.size(); ++k) {
    const RunSpec& spec = specs[k];
    progress.Start(static_cast<int>(k), Describe(spec));
    std::unique_ptr<Simulation> sim = scene.Make(OptionsFor(options, spec));
    Advance(sim.get(), {args.duration, 0.0, true}, nullptr);
    std::optional<Impact> first;
    for (const Impact& impact : sim->contacts().impacts()) {
      if (impact.tag == 0) {
        first = impact;
        break;
      }
    }
    const bool closed = first && !first->open;
    if (!closed) {
      ++incomplete;
      fmt::print(stderr, "contactlaws: warning: {}: {} within --duration={} s\n",
                 Describe(spec),
                 first ? "the first contact did not end" : "no contact", args.duration);
    }
    auto if_closed = [&](double v) { return closed ? Field(v) : std::string(); };
    out.Fields({std::string(LawName(spec.law)), Field(*spec.restitution),
                first ? if_closed(first->restitution_post()) : "",
                first ? Field(first->impact_velocity) : "",
                first ? Field(first->max_depth) : "", first ? Field(first->max_force) : "",
                first ? if_closed(first->time_separation - first->time_contact) : ""});
    rows.push_back({spec, first});
  }
  progress.Done();
  out.Commit();

  if (args.output != "-") {
    fmt::print("{:<20} {:>11} {:>12} {:>12} {:>14} {:>14} {:>13}\n", "law", "restitution",
               "e_post", "exact e_post", "max depth (m)", "max force (N)", "duration (s)");
    for (const Row& r : rows) {
      std::optional<double> post, duration, exact;
      if (r.first && !r.first->open) {
        post = r.first->restitution_post();
        duration = r.first->time_separation - r.first->time_contact;
      }
      if (r.spec.law != LawKind::kKelvinVoigt && *r.spec.restitution > 0) {
        exact = ExactRebound(HysteresisCoefficient(r.spec.law, *r.spec.restitution));
      }
      fmt::print("{:<20} {:>11} {:>12} {:>12} {:>14} {:>14} {:>13}\n", LawName(r.spec.law),
                 Field(*r.spec.restitution), Cell(post, "{:.6f}"), Cell(exact, "{:.6f}"),
                 r.first ? fmt::format("{:.6g}", r.first->max_depth) : "-",
                 r.first ? fmt::format("{:.6g}", r.first->max_force) : "-",
                 Cell(duration, "{:.6g}"));
    }
    fmt::print("exact e_post: the closed form a (1 + e) = ln((1 + a) / (1 - a e)), "
               "gravity neglected\nwrote {}\n", args.output);
  }
  return incomplete ? kExitIncomplete : 0;
}

int CheckCommand(const CheckArgs& args) {
  SimulationOptions options;
  if (args.law) options.overrides.law = ParseLaw("--law", *args.law);
  if (args.restitution) {
    options.overrides.restitution = ParseRestitution("--restitution", *args.restitution);
  }
  if (args.timestep) {
    RequirePositive("--timestep", *args.timestep, "s");
    options.timestep = args.timestep;
  }
  if (args.impact_velocity) {
    RequirePositive("--impact-velocity", *args.impact_velocity, "m/s");
  }
  const Scene scene(args.scene);
  std::unique_ptr<Simulation> sim = scene.Make(options);
  const mjModel* m = sim->model();
  mj_forward(m, sim->data());
  const ContactModel& cm = sim->contact_model();
  const double dt = m->opt.timestep;
  const char* integrators[] = {"euler", "rk4", "implicit"};

  fmt::print("{}: MuJoCo {}.{}.{}, timestep {} s, integrator {}, gravity ({}, {}, {}) m/s^2\n",
             scene.path(), MujocoVersion() / 100, MujocoVersion() / 10 % 10,
             MujocoVersion() % 10, dt,
             m->opt.integrator >= 0 && m->opt.integrator < 3 ? integrators[m->opt.integrator]
                                                              : "?",
             m->opt.gravity[0], m->opt.gravity[1], m->opt.gravity[2]);
  fmt::print("rule: a contact is resolved by >= {} steps of its estimated duration\n",
             kStepsPerContact);

  int coarse = 0;
  fmt::print("\n{} contactlaw tag(s)\n", cm.tags().size());
  for (const PairTag& tag : cm.tags()) {
    const LawParams& law = cm.pairs()[tag.pairs.front()].params;
    fmt::print("\ncontactlaw:{}: {} - {}, {} geom pair(s), law {}\n", tag.label, tag.geom1,
               tag.geom2, tag.pairs.size(), LawName(law.kind));
    if (law.kind == LawKind::kKelvinVoigt) {
      fmt::print("  restitution {}, linear_stiffness k {} N/m, damping c {}\n", law.restitution,
                 law.linear_stiffness,
                 law.damping ? fmt::format("{} N s/m", *law.damping)
                             : std::string("from e and the effective mass at each contact"));
    } else {
      fmt::print("  restitution {}{}, stiffness K {:.6g} N/m^{}, exponent n {}\n",
                 ReportedRestitution(law.kind, law.restitution),
                 law.kind == LawKind::kHertz ? " (elastic)" : "", law.stiffness, law.exponent,
                 law.exponent);
    }
    fmt::print("  min_impact_velocity {} m/s{}\n", law.min_impact_velocity,
               law.allow_tension ? ", allow_tension" : "");

    // the pair of this tag whose contact is shortest decides the timestep
    int worst = -1;
    ContactEstimate estimate;
    for (int p : tag.pairs) {
      const ContactEstimate e = EstimateContact(sim->contacts(), p, args.impact_velocity);
      if (worst < 0 || e.contact_duration < estimate.contact_duration) {
        worst = p;
        estimate = e;
      }
    }
    const GeomPair& pair = cm.pairs()[worst];
    fmt::print("  {}geoms {} - {}: effective mass {} kg, gap {}\n",
               tag.pairs.size() > 1 ? "shortest contact: " : "",
               ObjectName(m, mjOBJ_GEOM, pair.named[0]), ObjectName(m, mjOBJ_GEOM, pair.named[1]),
               estimate.effective_mass,
               estimate.gap ? fmt::format("{:.6g} m", *estimate.gap) : "out of reach");
    fmt::print("  impact velocity {:.6g} m/s ({})\n", estimate.impact_velocity,
               args.impact_velocity ? "--impact-velocity"
                                    : "estimated: closing speed, gravity over the gap, "
                                      "driven bodies' top speed");
    if (!std::isfinite(estimate.contact_duration)) {
      fmt::print("  contact duration: not estimated (nothing brings the geoms together, or "
                 "neither can move); give --impact-velocity\n");
      continue;
    }
    const double steps = estimate.contact_duration / dt;
    const bool ok = steps >= kStepsPerContact;
    coarse += !ok;
    fmt::print("  elastic ({}) contact: max depth {:.4g} m, duration {:.4g} s\n",
               law.kind == LawKind::kKelvinVoigt ? "k d" : "K d^n", estimate.max_depth,
               estimate.contact_duration);
    fmt::print("  {:.1f} steps per contact at {} s: {} (needs timestep <= {:.3g} s)\n", steps, dt,
               ok ? "ok" : "TOO COARSE", estimate.timestep());
  }

  fmt::print("\n{} driven bod{}\n", cm.drives().size(), cm.drives().size() == 1 ? "y" : "ies");
  for (const Drive& drive : cm.drives()) {
    fmt::print("contactdrive:{}: body {}, p(t) = ({}, {}, {}) + ({}, {}, {}) * {} m * sin({} rad/s "
               "* t + {} rad), top speed {:.6g} m/s\n",
               drive.label, ObjectName(m, mjOBJ_BODY, drive.body), drive.ref[0], drive.ref[1],
               drive.ref[2], drive.axis[0], drive.axis[1], drive.axis[2], drive.amplitude,
               drive.omega, drive.phase, std::abs(drive.amplitude * drive.omega));
  }
  if (coarse) {
    fmt::print("\nwarning: {} tag(s) need a smaller timestep (--timestep)\n", coarse);
  }
  return 0;
}

int LawsCommand() {
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

}  // namespace contactlaws::cli
