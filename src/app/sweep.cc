// Copyright contactlaws authors.

#include "app/sweep.h"

#include <cmath>
#include <functional>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "app/arena.h"
#include "app/csv_text.h"
#include "app/parallel.h"
#include "app/run_warnings.h"
#include "ident/wire.h"
#include "sim/run_report.h"
#include "sim/start_contact.h"

namespace contactlaws::app {
namespace {

RunOutput NotRun(const RunSpec& spec) {
  RunOutput out;
  out.status = RunOutput::Status::kNotRun;
  out.reason = "interrupted before it started";
  out.restitution = spec.restitution;
  return out;
}

// One run of a sweep, on any thread. Refused input and divergence make a
// failed run, not an exception: the sweep goes on.
RunOutput Execute(const Scene& scene, const SimulationOptions& options, const RunSpec& spec,
                  const std::vector<TimestepAdvice>& advice, const SweepOptions& sweep,
                  const OptionReader& reader, SweepMonitor* monitor) {
  RunOutput out;
  out.restitution = spec.restitution;
  try {
    std::unique_ptr<Simulation> sim = scene.Make(OptionsFor(options, spec));
    out.restitution =
        ReportedRestitution(spec.law, sim->contact_model().tags().front().restitution);
    std::vector<std::string> prefix = {std::string(LawName(spec.law)), Field(out.restitution)};
    if (spec.friction) prefix.emplace_back(FrictionName(*spec.friction));
    std::function<void(const std::vector<double>&)> on_row;
    if (sweep.record && sweep.keep_numbers) {
      on_row = [&](const std::vector<double>& row) {
        for (const double v : row) {
          if (!std::isfinite(v)) {
            throw Error(fmt::format("t = {} s: a NaN or infinite value in the trajectory",
                                    sim->time()));
          }
        }
        out.rows.insert(out.rows.end(), row.begin(), row.end());
      };
    } else if (sweep.record) {
      on_row = [&](const std::vector<double>& row) {
        if (!AppendRow(&out.trajectory, prefix, row)) {
          throw Error(fmt::format("t = {} s: a NaN or infinite value in the trajectory",
                                  sim->time()));
        }
      };
    }
    const AdvanceResult result = Advance(sim.get(), sweep.advance, on_row);
    double end_time = sim->time();
    if (result.status == AdvanceResult::Status::kDiverged) {
      out.status = RunOutput::Status::kFailed;
      out.reason =
          "diverged at " + DivergenceMessage(*sim, *result.divergence, advice, reader.spelling());
      end_time = result.divergence->time;
    } else if (result.status == AdvanceResult::Status::kInterrupted) {
      out.status = RunOutput::Status::kInterrupted;
      out.reason = fmt::format("interrupted at t = {:.6g} s", end_time);
      return out;
    }
    out.warnings = RunWarnings(*sim, result, reader);
    monitor->RunFinished(*sim);
    if (sweep.record && sweep.keep_numbers) {
      out.impact_table = ImpactTable(*sim, ImpactsOf(sim->contacts(), sweep.impact_rows));
    } else if (sweep.record) {
      const Table impacts = ImpactTable(*sim, ImpactsOf(sim->contacts(), sweep.impact_rows));
      for (size_t i = 0; i < impacts.rows(); ++i) {
        std::vector<std::string> fields = TableFields(impacts, i);
        // law, restitution, then the friction model as in the trajectories
        if (spec.friction) fields.emplace(fields.begin() + 2, FrictionName(*spec.friction));
        AppendFields(&out.impacts, fields);
      }
    }
    for (const Episode& impact : sim->contacts().impacts()) {
      if (impact.tag == 0) {
        out.first = impact;
        break;
      }
    }
    out.summary = Summarize(sim->contacts().impacts(), end_time, SettlingImpacts(*sim));
    out.dissipated = sim->contacts().DissipatedEnergy();
  } catch (const OptionError& e) {
    out.status = RunOutput::Status::kFailed;
    out.reason = Spelled(e, reader.spelling());
  } catch (const Error& e) {
    out.status = RunOutput::Status::kFailed;
    out.reason = e.what();
  }
  return out;
}

}  // namespace

// RunOutput's fields for the exchange between the ranks of a job.
template <typename Archive>
void serialize(Archive& archive, RunOutput& out) {
  static_assert(sizeof(RunOutput) == 488, "RunOutput changed: name its new field here");
  archive(out.status, out.reason, out.warnings, out.restitution, out.trajectory, out.impacts,
          out.rows, out.impact_table, out.summary, out.dissipated, out.first);
}

namespace {

// The runs of a cluster job: this rank's share computed (jobs at a time),
// then every run's output, in order, on every rank.
std::vector<RunOutput> RunShare(WorkSpread* spread, int count, int jobs,
                                const std::function<RunOutput(int)>& work,
                                const std::function<bool()>& should_stop,
                                const std::function<RunOutput(int)>& skipped) {
  std::vector<std::string> items(count);
  std::vector<double> seconds(count);  // each of this rank's runs'
  RunInOrder<RunOutput>(
      count, jobs,
      [&](int k) {
        if (!spread->Mine(k, count)) return RunOutput();
        const double start = ThreadSeconds();
        RunOutput out = work(k);
        seconds[k] = ThreadSeconds() - start;
        return out;
      },
      [&](int k, RunOutput& out) {
        if (spread->Mine(k, count)) items[k] = internal::Written(out);
      },
      should_stop, [&](int k) { return spread->Mine(k, count) ? skipped(k) : RunOutput(); });
  spread->Share(&items, seconds);
  std::vector<RunOutput> outputs;
  outputs.reserve(count);
  for (const std::string& item : items) outputs.push_back(internal::Read<RunOutput>(item));
  return outputs;
}

}  // namespace

namespace {

// laws "all": a law that needs a dissipation nobody gave (neither the
// scene's tags nor the dissipation option) is left out with a warning, not
// refused; named in laws, it is refused as any bad input is.
void LeaveOutLawsMissingADissipation(const OptionReader& reader, SweepInputs* in,
                                      SweepMonitor* monitor) {
  if (in->common.simulation.overrides.dissipation) return;
  std::vector<LawId> kept;
  for (const LawId law : in->laws) {
    if (ReadsDissipation(law)) {
      try {
        RunSpec spec{law, std::nullopt, std::nullopt};
        in->scene->Make(OptionsFor(in->common.simulation, spec));
      } catch (const Error&) {
        monitor->Warn(in->scene->path(),
                      fmt::format("{} leaves out {}: it needs a dissipation (give {}, s/m)",
                                  reader.Given("laws", "all"), LawName(law),
                                  reader.Name("dissipation")));
        continue;
      }
    }
    kept.push_back(law);
  }
  in->laws = std::move(kept);
}

}  // namespace

SweepInputs ReadSweepInputs(const OptionReader& reader, const std::string& scene,
                            const SweepInput& input, const char* default_restitutions,
                            SweepMonitor* monitor) {
  SweepInputs in;
  in.common = reader.Common(input);
  in.laws = reader.LawList("laws", input.laws);
  if (input.frictions) {
    if (input.friction) {
      reader.Refuse("frictions", *input.frictions,
                    fmt::format("goes without {}={} (each run takes one of the list)",
                                reader.Name("friction"), *input.friction));
    }
    in.frictions = reader.FrictionList("frictions", *input.frictions);
  }
  in.jobs = reader.Jobs(input.jobs);
  if (input.restitution || default_restitutions) {
    in.restitutions = reader.RestitutionList(
        "restitution", input.restitution ? *input.restitution : Value(default_restitutions));
  }
  in.scene = std::make_unique<Scene>(scene, LoadSizedModel(scene, in.common.simulation.overrides));
  if (input.laws == "all") LeaveOutLawsMissingADissipation(reader, &in, monitor);
  return in;
}

std::string Describe(const RunSpec& spec) {
  std::string what = spec.restitution ? fmt::format("{} e={}", LawName(spec.law), *spec.restitution)
                                      : std::string(LawName(spec.law));
  if (spec.friction) what += fmt::format(" friction={}", FrictionName(*spec.friction));
  return what;
}

SimulationOptions OptionsFor(SimulationOptions options, const RunSpec& spec) {
  options.overrides.law = spec.law;
  options.overrides.restitution = spec.restitution;
  if (spec.friction) options.overrides.friction = spec.friction;
  return options;
}

std::vector<std::vector<TimestepAdvice>> Prepare(const Scene& scene,
                                                 const SimulationOptions& options,
                                                 const std::vector<RunSpec>& specs,
                                                 bool auto_timestep, const OptionReader& reader,
                                                 SweepMonitor* monitor) {
  std::set<std::string> warned;
  std::vector<std::vector<TimestepAdvice>> advices;
  for (const RunSpec& spec : specs) {
    std::unique_ptr<Simulation> sim = scene.Make(OptionsFor(options, spec));
    for (const std::string& w : TagWarnings(sim->contact_model())) {
      if (warned.insert(w).second) monitor->TagWarning(w);
    }
    // the scene's start, whatever the run: once each
    const std::vector<StartContact> starts = StartContacts(sim.get());
    for (const std::string& text : DeepStartWarnings(*sim, starts, reader.spelling())) {
      if (warned.insert(text).second) monitor->Warn(scene.path(), text);
    }
    advices.push_back(AdviseTimestep(sim.get(), starts));
    if (auto_timestep) continue;  // the steps will resolve the contacts
    for (const std::string& text : TimestepWarnings(*sim, advices.back(), reader.spelling())) {
      if (warned.insert(text).second) {
        monitor->Warn(scene.path(), specs.size() > 1 ? Describe(spec) + ": " + text : text);
      }
    }
  }
  return advices;
}

const char* SweepRunStatusName(RunStatus status) {
  switch (status) {
    case RunStatus::kComplete: return "ok";
    case RunStatus::kDiverged: return "diverged";
    case RunStatus::kFailed: return "failed";
    case RunStatus::kInterrupted: return "interrupted";
    case RunStatus::kNotRun: return "not run";
  }
  return "?";
}

SweepStatus Sweep(const Scene& scene, const SimulationOptions& options,
                  const std::vector<RunSpec>& specs,
                  const std::vector<std::vector<TimestepAdvice>>& advices,
                  const SweepOptions& sweep, const OptionReader& reader, SweepMonitor* monitor,
                  const std::function<void(int, RunOutput&)>& deliver) {
  int failed = 0;
  bool interrupted = false;
  const int count = static_cast<int>(specs.size());
  auto work = [&](int k) {
    return Execute(scene, options, specs[k], advices[k], sweep, reader, monitor);
  };
  auto handle = [&](int k, RunOutput& out) {
    for (const std::string& w : out.warnings) {
      monitor->Warn(scene.path(), Describe(specs[k]) + ": " + w);
    }
    if (out.status == RunOutput::Status::kFailed) {
      ++failed;
      monitor->RunFailed(scene.path(), Describe(specs[k]), out.reason);
    }
    interrupted = interrupted || out.status == RunOutput::Status::kInterrupted ||
                  out.status == RunOutput::Status::kNotRun;
    deliver(k, out);
    monitor->RunDone(k, count, Describe(specs[k]));
  };
  auto should_stop = [&] {
    return sweep.advance.stop && sweep.advance.stop->load(std::memory_order_relaxed);
  };
  auto skipped = [&](int k) { return NotRun(specs[k]); };
  if (sweep.spread) {
    std::vector<RunOutput> outputs =
        RunShare(sweep.spread, count, sweep.jobs, work, should_stop, skipped);
    for (int k = 0; k < count; ++k) handle(k, outputs[k]);
  } else {
    RunInOrder<RunOutput>(count, sweep.jobs, work, handle, should_stop, skipped);
  }
  monitor->SweepDone();
  if (interrupted) return SweepStatus::kInterrupted;
  return failed ? SweepStatus::kFailed : SweepStatus::kComplete;
}

}  // namespace contactlaws::app
