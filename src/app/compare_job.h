// Copyright contactlaws authors.
//
// compare: every law x restitution (x friction model) of a scene run
// (app/sweep.h), each run's trajectory, impact log and summary as tables,
// and the printed table.

#ifndef CONTACTLAWS_APP_COMPARE_JOB_H_
#define CONTACTLAWS_APP_COMPARE_JOB_H_

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/options.h"
#include "app/sweep.h"
#include "app/table.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::app {

// compare's runs, read, validated and warned about before any runs: every
// law x restitution x friction model, their timestep advice, the first
// run's simulation (its columns), the sweep's options (no stop, no spread:
// the caller's).
struct ComparePlan {
  SweepInputs in;
  std::vector<RunSpec> specs;
  bool frictions = false;  // the runs compare friction models
  std::vector<std::vector<TimestepAdvice>> advices;
  std::unique_ptr<Simulation> first;
  SweepOptions sweep;
};
// impacts_per_point: the impact log per contact point.
ComparePlan PlanCompare(const OptionReader& reader, const std::string& scene,
                        const SweepInput& input, bool impacts_per_point, SweepMonitor* monitor);

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

// compare's three files as tables, run by run from outputs kept as numbers
// (SweepOptions::keep_numbers): trajectories (law, restitution[, friction],
// then the run's columns), impacts (the impact log, friction third),
// summary (SummaryColumns after the run's); and the printed table's rows.
class CompareTables {
 public:
  explicit CompareTables(const ComparePlan& plan);

  // Run spec's output, delivered in order; its rows are moved out.
  void Add(const RunSpec& spec, RunOutput& out);

  const Table& trajectories() const { return trajectories_; }
  const Table& impacts() const { return impacts_; }
  const Table& summary() const { return summary_; }
  const std::vector<CompareRow>& rows() const { return rows_; }

 private:
  bool frictions_;
  std::vector<std::string> columns_;
  Table trajectories_, impacts_, summary_;
  std::vector<CompareRow> rows_;
};

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_COMPARE_JOB_H_
