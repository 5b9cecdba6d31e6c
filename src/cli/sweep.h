// Copyright contactlaws authors.
//
// What compare and restitution share: a sweep of (law, restitution) runs of
// one scene, validated before any runs, run jobs at a time, delivered in
// order.

#ifndef CONTACTLAWS_CLI_SWEEP_H_
#define CONTACTLAWS_CLI_SWEEP_H_

#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/impact_table.h"
#include "app/table.h"
#include "cli/csv_file.h"
#include "cli/options.h"
#include "contactlaws/contactlaws.h"
#include "sim/summary.h"
#include "sim/timestep_advice.h"

namespace contactlaws::cli {

// One (law, restitution) combination of a sweep.
struct RunSpec {
  LawId law{};  // hertz unless set
  std::optional<double> restitution;  // nullopt: the scene's
  std::optional<FrictionKind> friction;  // nullopt: the scene's (compare --frictions)
};

// The options of compare and restitution as given.
struct SweepArgs : CommonArgs {
  std::string laws = "all";
  std::optional<std::string> restitution;  // list or range
  std::optional<std::string> frictions;    // compare: M1,M2,... or all
  std::string output_dir = "results";      // compare
  std::string output = "-";                // restitution
  bool quiet = false;
  std::optional<std::string> jobs;         // default: the number of cores
  bool impacts_per_point = false;          // compare
  std::FILE* report = stdout;              // where the table is printed
};

// What compare and restitution read the same way, in this order (so that the
// first bad option is the one refused): the common options, --laws, --jobs,
// --frictions, --restitution, the scene.
struct SweepInputs {
  CommonOptions common;
  std::vector<LawId> laws;
  std::vector<FrictionKind> frictions;  // empty: none given (the scene's)
  int jobs = 1;
  std::vector<double> restitutions;  // empty: none given, and no default
  std::unique_ptr<Scene> scene;
};

// default_restitutions: the list when --restitution is absent (nullptr: none).
SweepInputs ReadSweepInputs(const SweepArgs& args, const char* default_restitutions);

// "flores e=0.5", or the law alone for the scene's restitution; then
// " friction=lugre" for a run of compare --frictions.
std::string Describe(const RunSpec& spec);

// options with spec's law, restitution and friction model as overrides.
SimulationOptions OptionsFor(SimulationOptions options, const RunSpec& spec);

// --jobs: the number of cores when absent, else a whole number >= 1.
int Jobs(const std::optional<std::string>& jobs);

// Before any run: every run's tags are validated (bad input costs nothing),
// and a timestep too coarse for a tag's estimated contact is named once.
// Returns each run's advice, for its divergence message.
std::vector<std::vector<TimestepAdvice>> Prepare(const Scene& scene,
                                                 const SimulationOptions& options,
                                                 const std::vector<RunSpec>& specs,
                                                 bool auto_timestep);

// What one run of a sweep leaves for the thread that writes, in order.
struct RunOutput {
  enum class Status { kOk, kFailed, kInterrupted, kNotRun };
  Status status = Status::kOk;
  std::string reason;                 // failed, interrupted
  std::vector<std::string> warnings;  // for stderr
  std::optional<double> restitution;  // as reported (1 for Hertz, none when not read)
  std::string trajectory;             // CSV lines (compare)
  std::string impacts;                // CSV lines (compare)
  // compare with SweepOptions::keep_numbers: the trajectory's rows (the
  // run's columns, row by row) and its impact log, in place of the lines
  std::vector<double> rows;
  app::Table impact_table;
  RunSummary summary;
  double dissipated = 0;
  std::optional<Episode> first;        // the first episode of the first tag
};

// "ok", "failed", "interrupted", "not run".
const char* StatusName(RunOutput::Status status);

// How the runs of a sweep go and what they record.
struct SweepOptions {
  AdvanceOptions advance;
  // compare keeps each run's trajectory and impact log, restitution only
  // its summary
  bool record = false;
  // what is recorded kept as numbers (RunOutput::rows, impact_table), not
  // as CSV lines: Python's, which is never a cluster job
  bool keep_numbers = false;
  app::ImpactRows impact_rows = app::ImpactRows::kImpacts;
  int jobs = 1;
  bool quiet = false;  // no progress line
};

// Runs every spec (jobs at a time; in a cluster job, each rank its share)
// and hands each output to deliver, in order, on every rank (rank 0 alone
// writes files and prints). Returns the exit status: 0, kExitIncomplete when a run failed,
// kExitInterrupted after a stop request.
int Sweep(const Scene& scene, const SimulationOptions& options,
          const std::vector<RunSpec>& specs,
          const std::vector<std::vector<TimestepAdvice>>& advices, const SweepOptions& sweep,
          const std::function<void(int, RunOutput&)>& deliver);

// compare's runs, read, validated and warned about before any runs: every
// law x restitution x friction model (CompareSpecs), their timestep advice,
// the first run's simulation (its columns), the sweep's options.
struct ComparePlan {
  SweepInputs in;
  std::vector<RunSpec> specs;
  bool frictions = false;  // the runs compare friction models
  std::vector<std::vector<TimestepAdvice>> advices;
  std::unique_ptr<Simulation> first;
  SweepOptions sweep;
};
ComparePlan PlanCompare(const SweepArgs& args);

// One run's line of compare's printed table.
struct CompareRow {
  RunSpec spec;
  RunOutput::Status status;
  std::optional<double> restitution;
  RunSummary s;
  double dissipated;
};
// The printed table: a header, a line per run.
std::string CompareTableText(const std::vector<CompareRow>& rows, bool frictions);
// summary.csv's columns after the run's (law, restitution[, friction]).
std::vector<std::string> SummaryColumns();

// Creates dir (and its parents); throws Error naming it when it cannot.
std::string CreateDirectory(const std::string& dir);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_SWEEP_H_
