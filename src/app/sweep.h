// Copyright contactlaws authors.
//
// What compare and restitution share: a sweep of (law, restitution[,
// friction model]) runs of one scene, read and validated before any runs,
// run jobs at a time (or spread over the ranks of a cluster job), delivered
// in order. What the sweep has to say as it goes goes to its front-end's
// monitor.

#ifndef CONTACTLAWS_APP_SWEEP_H_
#define CONTACTLAWS_APP_SWEEP_H_

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/impact_table.h"
#include "app/options.h"
#include "app/table.h"
#include "contactlaws/contactlaws.h"
#include "ident/work_spread.h"
#include "sim/summary.h"
#include "sim/timestep_advice.h"

namespace contactlaws::app {

// One (law, restitution) combination of a sweep.
struct RunSpec {
  LawId law{};  // hertz unless set
  std::optional<double> restitution;  // nullopt: the scene's
  std::optional<FrictionKind> friction;  // nullopt: the scene's (compare's frictions)
};

// The options of compare and restitution as given.
struct SweepInput : CommonInput {
  std::string laws = "all";                // L1,L2,... or all
  std::optional<Value> restitution;        // a number, a list or a range
  std::optional<std::string> frictions;    // compare: M1,M2,... or all
  std::optional<Value> jobs;               // default: the number of cores
};

// What a sweep tells its front-end as it goes (the command line prints it
// on stderr, Python too). Every call but RunFinished is made on the thread
// that called the sweep; RunFinished on the run's.
class SweepMonitor {
 public:
  virtual ~SweepMonitor() = default;
  // A warning about the scene (its path).
  virtual void Warn(const std::string& scene, const std::string& what) = 0;
  // A tag's own warning, which names its file and tag.
  virtual void TagWarning(const std::string& what) = 0;
  // A line about scene: what settle moved.
  virtual void Note(const std::string& scene, const std::string& what) = 0;
  // A run failed, before it is delivered.
  virtual void RunFailed(const std::string& scene, const std::string& run,
                         const std::string& reason) = 0;
  // Run k of count ("flores e=0.5") delivered.
  virtual void RunDone(int k, int count, const std::string& run) {
    (void)k, (void)count, (void)run;
  }
  // A run's simulation after its last step, on the run's thread.
  virtual void RunFinished(const Simulation& sim) { (void)sim; }
  // The last run was delivered (a progress line ends).
  virtual void SweepDone() {}
};

// What compare and restitution read the same way, in this order (so that the
// first bad option is the one refused): the common options, laws, jobs,
// frictions, restitution, the scene.
struct SweepInputs {
  CommonOptions common;
  std::vector<LawId> laws;
  std::vector<FrictionKind> frictions;  // empty: none given (the scene's)
  int jobs = 1;
  std::vector<double> restitutions;  // empty: none given, and no default
  std::unique_ptr<Scene> scene;
};

// default_restitutions: the list when restitution is absent (nullptr: none).
// laws "all" leaves out, with a warning, a law that needs a dissipation
// nobody gave.
SweepInputs ReadSweepInputs(const OptionReader& reader, const std::string& scene,
                            const SweepInput& input, const char* default_restitutions,
                            SweepMonitor* monitor);

// "flores e=0.5", or the law alone for the scene's restitution; then
// " friction=lugre" for a run of compare's frictions.
std::string Describe(const RunSpec& spec);

// options with spec's law, restitution and friction model as overrides.
SimulationOptions OptionsFor(SimulationOptions options, const RunSpec& spec);

// Before any run: every run's tags are validated (bad input costs nothing),
// and a timestep too coarse for a tag's estimated contact is named once,
// the options spelled as reader does. Returns each run's advice, for its
// divergence message.
std::vector<std::vector<TimestepAdvice>> Prepare(const Scene& scene,
                                                 const SimulationOptions& options,
                                                 const std::vector<RunSpec>& specs,
                                                 bool auto_timestep, const OptionReader& reader,
                                                 SweepMonitor* monitor);

// What one run of a sweep leaves for the thread that delivers, in order.
struct RunOutput {
  using Status = RunStatus;  // kComplete, kFailed, kInterrupted or kNotRun
  Status status = Status::kComplete;
  std::string reason;                 // failed, interrupted
  std::vector<std::string> warnings;  // for the monitor
  std::optional<double> restitution;  // as reported (1 for Hertz, none when not read)
  std::string trajectory;             // CSV lines (compare)
  std::string impacts;                // CSV lines (compare)
  // compare with SweepOptions::keep_numbers: the trajectory's rows (the
  // run's columns, row by row) and its impact log, in place of the lines
  std::vector<double> rows;
  Table impact_table;
  RunSummary summary;
  double dissipated = 0;
  std::optional<Episode> first;        // the first episode of the first tag
};

// A run's status in a sweep's outputs: "ok" (kComplete), "failed" (a run
// that diverged fails, its reason says where), "interrupted", "not run".
const char* SweepRunStatusName(RunStatus status);

// How the runs of a sweep go and what they record.
struct SweepOptions {
  AdvanceOptions advance;
  // compare keeps each run's trajectory and impact log, restitution only
  // its summary
  bool record = false;
  // what is recorded kept as numbers (RunOutput::rows, impact_table), not
  // as CSV lines: Python's, which is never a cluster job
  bool keep_numbers = false;
  ImpactRows impact_rows = ImpactRows::kImpacts;
  int jobs = 1;
  // the ranks of a cluster job, each running its share (null: this
  // process runs every run)
  WorkSpread* spread = nullptr;
};

// How a sweep ended.
using SweepStatus = RunStatus;  // kComplete, kFailed or kInterrupted

// Runs every spec (jobs at a time; in a cluster job, each rank its share)
// and hands each output to deliver, in order, on every rank. The runs'
// warnings name options as reader does. kFailed when a run failed,
// kInterrupted after a stop request.
SweepStatus Sweep(const Scene& scene, const SimulationOptions& options,
                  const std::vector<RunSpec>& specs,
                  const std::vector<std::vector<TimestepAdvice>>& advices,
                  const SweepOptions& sweep, const OptionReader& reader, SweepMonitor* monitor,
                  const std::function<void(int, RunOutput&)>& deliver);

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_SWEEP_H_
