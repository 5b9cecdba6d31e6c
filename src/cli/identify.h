// Copyright contactlaws authors.
//
// The options that replay and fit share, parsed and validated, and the
// files they write (docs/identification.md).

#ifndef CONTACTLAWS_CLI_IDENTIFY_H_
#define CONTACTLAWS_CLI_IDENTIFY_H_

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "app/fit_job.h"
#include "app/identify_options.h"
#include "app/replay_job.h"
#include "cli/csv_file.h"
#include "cli/options.h"

namespace contactlaws::cli {

// replay's options; fit takes them all.
struct ReplayArgs : CommonArgs {
  std::string data;                    // the measured trajectories
  std::optional<std::string> output;   // DIR
  std::string start = "first";         // first or refit
  std::optional<std::string> refit_height;
  std::string refit_lead = "3";
  std::string refit_min_samples = "4";
  std::string metric = "e_q";
  std::optional<std::string> weights;  // P,A[,J] of the weighted metric
  std::optional<std::string> length;   // e_q's L, m
  std::optional<std::string> jobs;
  std::optional<std::string> law;
  std::optional<std::string> restitution;
  std::vector<std::string> set;        // KEY=VALUE on every tag
  std::string seed = "1";              // the bootstrap's (and fit's search and folds)
  std::optional<std::string> rest_plane;  // GEOM: its offset estimated from the data
  bool quiet = false;
  std::FILE* report = stdout;  // where the scores are printed
};

struct FitArgs : ReplayArgs {
  std::string params;
  std::optional<std::string> initial;    // KEY=VALUE,...: where the search starts
  std::optional<std::string> laws;       // L1,L2,... or all
  std::optional<std::string> frictions;  // M1,M2,... or all
  std::optional<std::string> validate;   // trajectories not fitted on
  std::string budget = "200";
  std::optional<std::string> folds;      // K: K-fold cross-validation over the trajectories
  std::optional<std::string> trim;       // F: the share of worst trajectories a score leaves out
  std::optional<std::string> profile;    // all or KEY,...: the winner's profile along them
  std::optional<std::string> profile_points;  // N per parameter
  std::optional<std::string> profile_budget;  // the others re-fitted at each point
};

// The options as the grammar takes them (app/identify_options.h): the same
// text.
app::ReplayInput InputOf(const ReplayArgs& args);
app::FitInput InputOf(const FitArgs& args);

// --seed, or Refuse.
uint64_t ParseSeed(const std::string& text);

// app::ReadReplayOptions under the flags, spread over the ranks of a
// cluster job. metric: the metric chosen.
ReplayOptions ParseReplayOptions(const ReplayArgs& args, const Scene& scene, Metric* metric);

// The trajectories of --data.
MeasuredData DataOf(const ReplayArgs& args);

// app::ReadFitRequest under the flags, spread over the ranks of a cluster
// job: every option but the stop and the progress; offset_lines: what
// GEOM.offset=rest estimated.
app::FitRequest ParseFitRequest(const FitArgs& args, const Scene& scene,
                                const MeasuredData& train_data,
                                std::vector<std::string>* offset_lines);

// The simulated samples in the data's own columns (trajectories.csv).
void WriteSimulated(const MeasuredData& data, const app::SimulatedSamples& simulated,
                    CsvFile* file);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_IDENTIFY_H_
