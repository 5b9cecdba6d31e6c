// Copyright contactlaws authors.

#include "cli/commands.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/csv_file.h"
#include "cli/parallel.h"
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

int Jobs(const std::optional<int>& jobs) {
  if (!jobs) return DefaultJobs();
  if (*jobs < 1) Refuse("--jobs", fmt::format("{}", *jobs), "must be a whole number >= 1");
  return *jobs;
}

// Progress lines on stderr, only when it is a terminal.
class Progress {
 public:
  Progress(int total, bool quiet) : total_(total), enabled_(!quiet && isatty(STDERR_FILENO)) {}
  ~Progress() { Done(); }
  // Ends the progress line, before anything else is printed.
  void Done() {
    if (enabled_ && started_) fmt::print(stderr, "\r\033[K");
    started_ = false;
  }
  void Finished(int k, const std::string& what) {
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

void Warn(const std::string& scene, const std::string& what) {
  fmt::print(stderr, "contactlaws: warning: {}: {}\n", scene, what);
}

// Before any run: every run's tags are validated (bad input costs nothing),
// and a timestep too coarse for a tag's estimated contact is named once.
// Returns each run's advice, for its divergence message.
std::vector<std::vector<TimestepAdvice>> Prepare(const Scene& scene,
                                                 const SimulationOptions& options,
                                                 const std::vector<RunSpec>& specs,
                                                 bool auto_timestep) {
  std::set<std::string> warned;
  std::vector<std::vector<TimestepAdvice>> advices;
  for (const RunSpec& spec : specs) {
    std::unique_ptr<Simulation> sim = scene.Make(OptionsFor(options, spec));
    advices.push_back(AdviseTimestep(sim.get()));
    if (auto_timestep) continue;  // the steps will resolve the contacts
    for (const TimestepAdvice& advice : advices.back()) {
      if (!advice.coarse) continue;
      const std::string text = CoarseTimestepWarning(*sim, advice);
      if (warned.insert(text).second) {
        Warn(scene.path(), specs.size() > 1 ? Describe(spec) + ": " + text : text);
      }
    }
  }
  return advices;
}

// The warnings a finished run leaves: energy growth, MuJoCo's own.
std::vector<std::string> RunWarnings(const Simulation& sim, const AdvanceResult& result) {
  std::vector<std::string> warnings;
  if (result.energy_growth) warnings.push_back(*result.energy_growth);
  for (const MujocoWarning& w : sim.Warnings()) {
    warnings.push_back(fmt::format("MuJoCo: {} ({} time{})", w.text, w.count,
                                   w.count == 1 ? "" : "s"));
    NoteReportedMujocoWarning(w.text);
  }
  return warnings;
}

// A table cell: "-" for a value that does not exist.
std::string Cell(const std::optional<double>& value, const char* format) {
  return value ? fmt::format(fmt::runtime(format), *value) : "-";
}

void PrintRunSummary(const Simulation& sim, double end_time, std::FILE* out) {
  const ContactModel& cm = sim.contact_model();
  fmt::print(out, "{:<20} {:<20} {:>11} {:>8} {:>14} {:>14}\n", "pair", "law", "restitution",
             "impacts", "first e_post", "max force (N)");
  for (int t = 0; t < static_cast<int>(cm.tags().size()); ++t) {
    const PairTag& tag = cm.tags()[t];
    std::vector<Impact> impacts;
    for (const Impact& impact : sim.contacts().impacts()) {
      if (impact.tag == t) impacts.push_back(impact);
    }
    const RunSummary s = Summarize(impacts, end_time);
    fmt::print(out, "{:<20} {:<20} {:>11} {:>8} {:>14} {:>14.6g}\n", tag.label,
               LawName(tag.law), tag.law == LawKind::kHertz ? "-" : Field(tag.restitution),
               s.impacts, Cell(s.restitution_post, "{:.6f}"), s.max_force);
  }
}

// What one run of a sweep leaves for the thread that writes, in order.
struct RunOutput {
  enum class Status { kOk, kFailed, kInterrupted, kNotRun };
  Status status = Status::kOk;
  std::string reason;                 // failed, interrupted
  std::vector<std::string> warnings;  // for stderr
  double restitution = 0;             // as reported (1 for Hertz)
  std::string trajectory;             // CSV lines (compare)
  std::string impacts;                // CSV lines (compare)
  RunSummary summary;
  double dissipated = 0;
  std::optional<Impact> first;        // the first episode of the first tag
};

const char* StatusName(RunOutput::Status status) {
  switch (status) {
    case RunOutput::Status::kOk: return "ok";
    case RunOutput::Status::kFailed: return "failed";
    case RunOutput::Status::kInterrupted: return "interrupted";
    case RunOutput::Status::kNotRun: return "not run";
  }
  return "?";
}

RunOutput NotRun(const RunSpec& spec) {
  RunOutput out;
  out.status = RunOutput::Status::kNotRun;
  out.reason = "interrupted before it started";
  out.restitution = spec.restitution.value_or(0.0);
  return out;
}

// One run of a sweep, on any thread. Refused input and divergence make a
// failed run, not an exception: the sweep goes on.
RunOutput Execute(const Scene& scene, const SimulationOptions& options, const RunSpec& spec,
                  const std::vector<TimestepAdvice>& advice, const AdvanceOptions& advance,
                  bool record) {
  RunOutput out;
  out.restitution = spec.restitution.value_or(0.0);
  try {
    std::unique_ptr<Simulation> sim = scene.Make(OptionsFor(options, spec));
    out.restitution = ReportedRestitution(spec.law, sim->contact_model().tags().front().restitution);
    const std::vector<std::string> prefix = {std::string(LawName(spec.law)),
                                             Field(out.restitution)};
    std::function<void(const std::vector<double>&)> on_row;
    if (record) {
      on_row = [&](const std::vector<double>& row) {
        if (!AppendRow(&out.trajectory, prefix, row)) {
          throw Error(fmt::format("t = {} s: a NaN or infinite value in the trajectory",
                                  sim->time()));
        }
      };
    }
    const AdvanceResult result = Advance(sim.get(), advance, on_row);
    double end_time = sim->time();
    if (result.status == AdvanceResult::Status::kDiverged) {
      out.status = RunOutput::Status::kFailed;
      out.reason = "diverged at " + DivergenceMessage(*sim, *result.divergence, advice);
      end_time = result.divergence->time;
    } else if (result.status == AdvanceResult::Status::kInterrupted) {
      out.status = RunOutput::Status::kInterrupted;
      out.reason = fmt::format("interrupted at t = {:.6g} s", end_time);
      return out;
    }
    out.warnings = RunWarnings(*sim, result);
    if (record) {
      for (const Impact& impact : sim->contacts().impacts()) {
        AppendFields(&out.impacts, ImpactFields(*sim, impact));
      }
    }
    for (const Impact& impact : sim->contacts().impacts()) {
      if (impact.tag == 0) {
        out.first = impact;
        break;
      }
    }
    out.summary = Summarize(sim->contacts().impacts(), end_time);
    out.dissipated = sim->contacts().DissipatedEnergy();
  } catch (const Error& e) {
    out.status = RunOutput::Status::kFailed;
    out.reason = e.what();
  }
  return out;
}

// Runs every spec (jobs at a time) and hands each output to deliver, in
// order. Returns the exit status: 0, kExitIncomplete when a run failed,
// kExitInterrupted after a stop request.
int Sweep(const Scene& scene, const SimulationOptions& options,
          const std::vector<RunSpec>& specs,
          const std::vector<std::vector<TimestepAdvice>>& advices,
          const AdvanceOptions& advance, bool record, int jobs, bool quiet,
          const std::function<void(int, RunOutput&)>& deliver) {
  Progress progress(static_cast<int>(specs.size()), quiet);
  int failed = 0;
  bool interrupted = false;
  RunInOrder<RunOutput>(
      static_cast<int>(specs.size()), jobs,
      [&](int k) { return Execute(scene, options, specs[k], advices[k], advance, record); },
      [&](int k, RunOutput& out) {
        progress.Done();  // what deliver or the warnings print starts a line
        for (const std::string& w : out.warnings) Warn(scene.path(), Describe(specs[k]) + ": " + w);
        if (out.status == RunOutput::Status::kFailed) {
          ++failed;
          fmt::print(stderr, "contactlaws: {}: {}: run failed: {}\n", scene.path(),
                     Describe(specs[k]), out.reason);
        }
        interrupted = interrupted || out.status == RunOutput::Status::kInterrupted ||
                      out.status == RunOutput::Status::kNotRun;
        deliver(k, out);
        progress.Finished(k, Describe(specs[k]));
      },
      StopRequested, [&](int k) { return NotRun(specs[k]); });
  progress.Done();
  if (interrupted) {
    fmt::print(stderr, "contactlaws: interrupted: the finished runs are written\n");
    return kExitInterrupted;
  }
  return failed ? kExitIncomplete : 0;
}

std::string CreateDirectory(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) {
    throw Error(fmt::format("{}: cannot create the output directory ({})", dir, error.message()));
  }
  return dir;
}

}  // namespace

int RunCommand(const RunArgs& args) {
  SimulationOptions options = ParseCommon(args);
  const std::optional<AutoTimestepOptions> auto_timestep = ParseAutoTimestep(args);
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

  const std::vector<TimestepAdvice> advice = AdviseTimestep(sim.get());
  for (const TimestepAdvice& a : advice) {
    if (a.coarse && !auto_timestep) Warn(scene.path(), CoarseTimestepWarning(*sim, a));
  }
  if (trajectory) trajectory->Header(sim->Columns());
  const AdvanceOptions advance{args.duration, trajectory ? args.sample_rate : 0.0, false,
                               auto_timestep};
  const AdvanceResult result =
      Advance(sim.get(), advance, [&](const std::vector<double>& row) { trajectory->Row(row); });
  if (result.status == AdvanceResult::Status::kInterrupted) {
    fmt::print(stderr, "contactlaws: interrupted at t = {:.6g} s: no file written\n",
               sim->time());
    return kExitInterrupted;
  }
  for (const std::string& w : RunWarnings(*sim, result)) Warn(scene.path(), w);

  // what was computed up to a divergence is valid, and written
  const double end_time =
      result.divergence ? result.divergence->time : sim->time();
  if (trajectory) trajectory->Commit();
  if (impacts) {
    impacts->Header(ImpactColumns());
    for (const Impact& impact : sim->contacts().impacts()) {
      impacts->Fields(ImpactFields(*sim, impact));
    }
    impacts->Commit();
  }
  PrintRunSummary(*sim, end_time, args.output && *args.output == "-" ? stderr : stdout);
  if (result.divergence) {
    fmt::print(stderr, "contactlaws: {}: run stopped: diverged at {}\n", scene.path(),
               DivergenceMessage(*sim, *result.divergence, advice));
    return kExitIncomplete;
  }
  return 0;
}

int CompareCommand(const SweepArgs& args) {
  const SimulationOptions options = ParseCommon(args);
  const std::optional<AutoTimestepOptions> auto_timestep = ParseAutoTimestep(args);
  const std::vector<LawKind> laws = ParseLawList("--laws", args.laws);
  const int jobs = Jobs(args.jobs);
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
  const std::vector<std::vector<TimestepAdvice>> advices =
      Prepare(scene, options, specs, auto_timestep.has_value());

  CreateDirectory(args.output_dir);
  CsvFile trajectories(args.output_dir + "/trajectories.csv");
  CsvFile impacts(args.output_dir + "/impacts.csv");
  CsvFile summary(args.output_dir + "/summary.csv");
  {
    std::vector<std::string> columns = {"law", "restitution"};
    for (std::string& c : scene.Make(OptionsFor(options, specs.front()))->Columns()) {
      columns.push_back(std::move(c));
    }
    trajectories.Header(columns);
  }
  impacts.Header(ImpactColumns());
  summary.Header({"law", "restitution", "impacts", "restitution_post", "max_depth", "max_force",
                  "contact_duration", "time_to_rest", "dissipated_energy", "status", "reason"});

  struct Row {
    RunSpec spec;
    RunOutput::Status status;
    double restitution;
    RunSummary s;
    double dissipated;
  };
  std::vector<Row> rows;
  const int status = Sweep(
      scene, options, specs, advices, {args.duration, args.sample_rate, false, auto_timestep}, true, jobs,
      args.quiet,
      [&](int k, RunOutput& out) {
        const RunSpec& spec = specs[k];
        const std::string law(LawName(spec.law));
        if (out.status == RunOutput::Status::kOk || out.status == RunOutput::Status::kFailed) {
          // a failed run's rows up to its divergence are valid; an
          // interrupted run's are not written at all
          trajectories.Write(out.trajectory);
          impacts.Write(out.impacts);
        }
        const RunSummary& s = out.summary;
        if (out.status == RunOutput::Status::kOk) {
          summary.Fields({law, Field(out.restitution), Field(s.impacts),
                          Field(s.restitution_post), Field(s.max_depth), Field(s.max_force),
                          Field(s.contact_duration), Field(s.time_to_rest),
                          Field(out.dissipated), "ok", ""});
        } else {
          // a failed run's numbers are not to be trusted: only its status
          summary.Fields({law, Field(out.restitution), "", "", "", "", "", "", "",
                          StatusName(out.status), out.reason});
        }
        rows.push_back({spec, out.status, out.restitution, s, out.dissipated});
        trajectories.Flush();
        impacts.Flush();
        summary.Flush();
      });
  trajectories.Commit();
  impacts.Commit();
  summary.Commit();

  fmt::print("{:<20} {:>11} {:>8} {:>12} {:>14} {:>14} {:>13} {:>13} {:>15}\n", "law",
             "restitution", "impacts", "first e_post", "max depth (m)", "max force (N)",
             "duration (s)", "at rest (s)", "dissipated (J)");
  for (const Row& r : rows) {
    if (r.status != RunOutput::Status::kOk) {
      fmt::print("{:<20} {:>11} {}\n", LawName(r.spec.law), Field(r.restitution),
                 StatusName(r.status));
      continue;
    }
    fmt::print("{:<20} {:>11} {:>8} {:>12} {:>14.6g} {:>14.6g} {:>13} {:>13} {:>15.6g}\n",
               LawName(r.spec.law), Field(r.restitution), r.s.impacts,
               Cell(r.s.restitution_post, "{:.6f}"), r.s.max_depth, r.s.max_force,
               Cell(r.s.contact_duration, "{:.6g}"), Cell(r.s.time_to_rest, "{:.6g}"),
               r.dissipated);
  }
  fmt::print("wrote {0}/trajectories.csv, {0}/impacts.csv, {0}/summary.csv\n", args.output_dir);
  return status;
}

int RestitutionCommand(const SweepArgs& args) {
  const SimulationOptions options = ParseCommon(args);
  const std::optional<AutoTimestepOptions> auto_timestep = ParseAutoTimestep(args);
  const std::vector<LawKind> laws = ParseLawList("--laws", args.laws);
  const int jobs = Jobs(args.jobs);
  const std::vector<double> restitutions =
      ParseRestitutionList("--restitution", args.restitution.value_or(kDefaultSweep));
  std::vector<RunSpec> specs;
  for (LawKind law : laws) {
    for (double e : restitutions) specs.push_back({law, e});
  }
  const Scene scene(args.scene);
  const std::vector<std::vector<TimestepAdvice>> advices =
      Prepare(scene, options, specs, auto_timestep.has_value());

  CsvFile out(args.output);
  out.Header({"law", "restitution", "restitution_post", "impact_velocity", "max_depth",
              "max_force", "contact_duration"});
  struct Row {
    RunSpec spec;
    std::optional<Impact> first;
  };
  std::vector<Row> rows;
  int incomplete = 0;
  int status = Sweep(
      scene, options, specs, advices, {args.duration, 0.0, true, auto_timestep}, false, jobs, args.quiet,
      [&](int k, RunOutput& run) {
        const RunSpec& spec = specs[k];
        const std::optional<Impact>& first = run.first;
        const bool closed = run.status == RunOutput::Status::kOk && first && !first->open;
        if (run.status == RunOutput::Status::kOk && !closed) {
          ++incomplete;
          Warn(scene.path(), fmt::format("{}: {} within --duration={} s", Describe(spec),
                                         first ? "the first contact did not end" : "no contact",
                                         args.duration));
        }
        if (run.status != RunOutput::Status::kOk && run.status != RunOutput::Status::kFailed) {
          return;  // interrupted: no row
        }
        const bool known = run.status == RunOutput::Status::kOk && first;
        auto if_known = [&](double v) { return known ? Field(v) : std::string(); };
        auto if_closed = [&](double v) { return closed ? Field(v) : std::string(); };
        out.Fields({std::string(LawName(spec.law)), Field(*spec.restitution),
                    first ? if_closed(first->restitution_post()) : "",
                    first ? if_known(first->impact_velocity) : "",
                    first ? if_known(first->max_depth) : "",
                    first ? if_known(first->max_force) : "",
                    first ? if_closed(first->time_separation - first->time_contact) : ""});
        rows.push_back({spec, known ? first : std::nullopt});
      });
  out.Commit();
  if (status == 0 && incomplete) status = kExitIncomplete;

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
  return status;
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
  for (int t = 0; t < static_cast<int>(cm.tags().size()); ++t) {
    const PairTag& tag = cm.tags()[t];
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
    const TagEstimate shortest = EstimateTag(sim->contacts(), t, args.impact_velocity);
    const int worst = shortest.pair;
    const ContactEstimate& estimate = shortest.estimate;
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
