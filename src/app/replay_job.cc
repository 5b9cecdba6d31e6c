// Copyright contactlaws authors.

#include "app/replay_job.h"

#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "app/arena.h"

namespace contactlaws::app {
namespace {

// A result column's value: what is not finite is not known.
double Known(double value) {
  return std::isfinite(value) ? value : std::numeric_limits<double>::quiet_NaN();
}

// "3 of 300 diverged (...)" or "".
std::string DivergedText(const std::vector<ReplayedTrajectory>& replayed) {
  int diverged = 0;
  for (const ReplayedTrajectory& r : replayed) {
    diverged += r.status == ReplayedTrajectory::Status::kDiverged;
  }
  if (diverged == 0) return "";
  return fmt::format("{} of {} diverged (scored with their last finite state)", diverged,
                     replayed.size());
}

// What settling moved over the trajectories' starts, in one line.
std::string SettledText(const std::vector<ReplayedTrajectory>& replayed) {
  int starts = 0, farthest = -1;
  for (size_t i = 0; i < replayed.size(); ++i) {
    if (replayed[i].settled_bodies == 0) continue;
    ++starts;
    if (farthest < 0 || replayed[i].settled_distance > replayed[farthest].settled_distance) {
      farthest = static_cast<int>(i);
    }
  }
  if (starts == 0) {
    return "settle: no body touches another at any trajectory's start: nothing moved";
  }
  return fmt::format("settled the bodies in contact at the start of {} of {} trajectories: the "
                     "farthest moved {:.3g} m (trajectory {})",
                     starts, replayed.size(), replayed[farthest].settled_distance, farthest);
}

const char* StartName(StartRule rule) { return rule == StartRule::kRefit ? "refit" : "first"; }

}  // namespace

Scene LoadReplayScene(const std::string& path) {
  // the arena sized to the scene: each trajectory's mj_resetData zeroes all of it
  return Scene(path, LoadSizedModel(path, Overrides{}));
}

ReplayScores ScoresOf(const MeasuredData& data, const std::vector<ReplayedTrajectory>& replayed) {
  ReplayScores s;
  for (size_t i = 0; i < replayed.size(); ++i) {
    const ReplayedTrajectory& r = replayed[i];
    s.trajectory.push_back(data.trajectories[i].name);
    s.samples.push_back(r.score.samples);
    s.start.push_back(r.start);
    s.e_q.push_back(Known(r.score.e_q));
    s.position_rms.push_back(Known(r.score.position_rms));
    s.angle_rms.push_back(Known(r.score.angle_rms));
    s.joint_rms.push_back(Known(r.score.joint_rms));
    s.weighted.push_back(Known(r.score.weighted));
    s.status.push_back(r.status);
  }
  return s;
}

SimulatedSamples SimulatedOf(const MeasuredData& data,
                             const std::vector<ReplayedTrajectory>& replayed) {
  SimulatedSamples out;
  out.columns = data.columns;
  const size_t width = data.columns.size();
  for (size_t i = 0; i < replayed.size(); ++i) {
    const ReplayedTrajectory& r = replayed[i];
    const size_t samples = r.simulated.size() / width;
    for (size_t k = 0; k < samples; ++k) {
      out.trajectory.push_back(static_cast<int>(i));
      out.time.push_back(data.trajectories[i].time[r.start + k]);
    }
    out.values.insert(out.values.end(), r.simulated.begin(),
                      r.simulated.begin() + samples * width);
  }
  return out;
}

Table ScoresTable(const ReplayScores& s) {
  using Kind = Column::Kind;
  Table table({{"trajectory", Kind::kText},
               {"samples", Kind::kCount},
               {"start", Kind::kCount},
               {"e_q", Kind::kNumber},
               {"position_rms", Kind::kNumber},
               {"angle_rms", Kind::kNumber},
               {"joint_rms", Kind::kNumber},
               {"weighted", Kind::kNumber},
               {"status", Kind::kText}});
  for (size_t i = 0; i < s.trajectory.size(); ++i) {
    table.AddRow({Text(s.trajectory[i]), Count(s.samples[i]), Count(s.start[i]), Number(s.e_q[i]),
                  Number(s.position_rms[i]), Number(s.angle_rms[i]), Number(s.joint_rms[i]),
                  Number(s.weighted[i]), Text(ReplayStatusName(s.status[i]))});
  }
  return table;
}

const char* ReplayStatusName(RunStatus status) {
  switch (status) {
    case RunStatus::kComplete: return "complete";
    case RunStatus::kDiverged: return "diverged";
    case RunStatus::kFailed: return "failed";
    case RunStatus::kInterrupted: return "interrupted";
    case RunStatus::kNotRun: return "not run";
  }
  return "";
}

ReplayJob::ReplayJob(const Scene& scene, const MeasuredData& data, ReplayRequest request)
    : scene_(scene), data_(data), request_(std::move(request)), replay_(scene, data) {
  if (request_.rest_plane) {
    offset_ = EstimateOffset(scene, *request_.rest_plane, data, request_.seed);
  }
}

ReplayResult ReplayJob::Run() const {
  ReplayOptions options = request_.options;
  options.keep_trajectories = request_.keep_trajectories;
  if (const auto stop = request_.stop.Callback()) options.should_stop = stop;
  ReplayResult result;
  result.replayed = replay_.Run(options);
  for (const ReplayedTrajectory& r : result.replayed) {
    result.interrupted |= r.status == ReplayedTrajectory::Status::kInterrupted;
  }
  if (result.interrupted) return result;
  result.scores = ScoresOf(data_, result.replayed);
  if (request_.keep_trajectories) result.simulated = SimulatedOf(data_, result.replayed);
  result.offset = offset_;

  result.report = fmt::format(
      "{}: {} trajectories of {} (start {}; means and medians with their 95% bootstrap "
      "interval over the trajectories):\n",
      scene_.path(), result.replayed.size(), data_.source, StartName(options.start));
  result.report += ReadableText("  ", data_, result.replayed, request_.metric, request_.seed);
  result.report += RestingGapsText("  ", data_, result.replayed, request_.seed);
  if (offset_) result.report += fmt::format("  {}\n", OffsetText(*request_.rest_plane, *offset_));
  result.diverged = DivergedText(result.replayed);
  if (options.simulation.settle) result.settled = SettledText(result.replayed);
  return result;
}

}  // namespace contactlaws::app
