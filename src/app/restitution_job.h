// Copyright contactlaws authors.
//
// restitution: the first impact of every law x restitution on a scene (the
// paper's Fig. 7), run as a sweep (app/sweep.h): a table of each run's first
// rebound against its closed form, and the printed table.

#ifndef CONTACTLAWS_APP_RESTITUTION_JOB_H_
#define CONTACTLAWS_APP_RESTITUTION_JOB_H_

#include <string>
#include <vector>

#include "app/options.h"
#include "app/sweep.h"
#include "app/table.h"

namespace contactlaws::app {

// The restitutions swept when none are given: the paper's Fig. 7.
inline constexpr char kDefaultSweep[] = "0.1:1.0:0.1";

// The runs, read, validated and warned about before any runs: every law x
// restitution, their timestep advice, the sweep's options (no stop, no
// spread: the caller's).
struct RestitutionPlan {
  SweepInputs in;
  std::vector<RunSpec> specs;
  std::vector<std::vector<TimestepAdvice>> advices;
  SweepOptions sweep;
};
RestitutionPlan PlanRestitution(const OptionReader& reader, const std::string& scene,
                                const SweepInput& input, SweepMonitor* monitor);

struct RestitutionResult {
  // a row per run that finished or failed (a failed one's numbers not
  // known): law, restitution, restitution_post (its first rebound's e),
  // impact_velocity m/s, max_depth m, max_force N, contact_duration s; not
  // known (NaN) where the run has no such value
  Table table;
  // the printed table: a line per row, each with its closed-form e_post
  std::string text;
  SweepStatus status = SweepStatus::kComplete;
  // runs whose first contact did not end within the duration (each warned)
  int incomplete = 0;
};

// Runs plan's sweep (its stop and spread set by the caller).
RestitutionResult RunRestitution(const RestitutionPlan& plan, const OptionReader& reader,
                                 SweepMonitor* monitor);

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_RESTITUTION_JOB_H_
