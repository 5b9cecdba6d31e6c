// Copyright contactlaws authors.
//
// replay as users ask for it: measured trajectories simulated on a tagged
// scene from their starts and scored (replay.h), the scores as columns of
// numbers, the simulated samples as a table in the data's own columns, and
// what is said of them to a person (score_text.h). The command line writes
// the columns as replay.csv and trajectories.csv and prints the report;
// Python turns them into DataFrames.

#ifndef CONTACTLAWS_APP_REPLAY_JOB_H_
#define CONTACTLAWS_APP_REPLAY_JOB_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/score_text.h"
#include "app/stop.h"
#include "app/table.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::app {

// The scene at path with its arena sized for many runs of one model
// (arena.h), as replay and fit load it.
Scene LoadReplayScene(const std::string& path);

struct ReplayRequest {
  ReplayOptions options;  // its should_stop is the stop token's
  Metric metric = Metric::kEq;  // summarised first in the report
  uint64_t seed = 1;            // the bootstraps' (report intervals, the offset's)
  // a plane geom whose offset is estimated from where the data rest
  std::optional<std::string> rest_plane;
  bool keep_trajectories = true;  // ReplayResult::simulated
  StopToken stop;
};

// A row per trajectory, in the data's order (replay.csv).
struct ReplayScores {
  std::vector<std::string> trajectory;
  std::vector<int> samples;  // compared
  std::vector<int> start;    // the sample the simulation started from
  // the metrics (replay.h), NaN where not known
  std::vector<double> e_q, position_rms, angle_rms, joint_rms, weighted;
  std::vector<ReplayedTrajectory::Status> status;
};

// The simulated samples, a row per sample compared (trajectories.csv).
struct SimulatedSamples {
  std::vector<std::string> columns;  // the data's own, in its units
  std::vector<int> trajectory;       // each row's index in the data
  std::vector<double> time;          // s, the measured sample's
  std::vector<double> values;        // rows x columns, row by row
};

struct ReplayResult {
  bool interrupted = false;  // stopped: the scores are not all there
  std::vector<ReplayedTrajectory> replayed;
  ReplayScores scores;
  SimulatedSamples simulated;  // with keep_trajectories
  std::optional<OffsetEstimate> offset;  // with rest_plane
  // The lines said to a person: the scores' summaries (report) and what
  // deserves a warning or a note (diverged, settled; empty when nothing).
  std::string report;
  std::string diverged;
  std::string settled;
};

// The columns of replayed, trajectories of data.
ReplayScores ScoresOf(const MeasuredData& data, const std::vector<ReplayedTrajectory>& replayed);
SimulatedSamples SimulatedOf(const MeasuredData& data,
                             const std::vector<ReplayedTrajectory>& replayed);

// scores as a table (replay.csv's columns): trajectory, samples, start,
// e_q, position_rms, angle_rms, joint_rms, weighted, status.
Table ScoresTable(const ReplayScores& scores);

// A trajectory's status in replay's tables: "complete", "diverged" or
// "interrupted" (the others are not a replay's).
const char* ReplayStatusName(RunStatus status);

class ReplayJob {
 public:
  // Binds data to scene (Replay's refusals) and estimates the rest plane's
  // offset (EstimateOffset's): every refusal before any run. Keeps
  // references to scene and data.
  ReplayJob(const Scene& scene, const MeasuredData& data, ReplayRequest request);

  ReplayResult Run() const;

 private:
  const Scene& scene_;
  const MeasuredData& data_;
  const ReplayRequest request_;
  const Replay replay_;
  std::optional<OffsetEstimate> offset_;
};

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_REPLAY_JOB_H_
