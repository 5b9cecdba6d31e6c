// Copyright contactlaws authors.

#include "contactlaws/contact_memory.h"

#include <algorithm>

namespace contactlaws {

double TouchTime(const PointEvaluation& e, double t) {
  const double mean_rate = 0.5 * (e.depth_rate + e.touch_velocity);
  return mean_rate > 0 ? t - e.depth / mean_rate : t;
}

double DissipatedPower(const std::vector<PointEvaluation>& points) {
  double power = 0;
  for (const PointEvaluation& e : points) power += e.dissipated_power;
  return power;
}

// ---------------------------------------------------------------------------

EpisodeLog::EpisodeLog(int slots, int tags) : slot_impact_(slots, -1), tag_count_(tags, 0) {}

void EpisodeLog::Reset() {
  std::fill(slot_impact_.begin(), slot_impact_.end(), -1);
  std::fill(tag_count_.begin(), tag_count_.end(), 0);
  open_.clear();
  impacts_.clear();
  tracks_.clear();
  commits_ = 0;
}

void EpisodeLog::Commit(double t, const std::vector<PointEvaluation>& points) {
  ++commits_;
  for (const PointEvaluation& e : points) {
    int& index = slot_impact_[e.slot];
    // a new point opens its episode
    if (index < 0) {
      Impact impact;
      impact.pair = e.pair;
      impact.tag = e.tag;
      impact.index = ++tag_count_[impact.tag];
      impact.impact_velocity = e.touch_velocity;
      impact.time_contact = TouchTime(e, t);
      index = static_cast<int>(impacts_.size());
      impacts_.push_back(impact);
      tracks_.push_back(Track{e.slot});
      open_.push_back(index);
    }
    // an open one advances
    Impact& impact = impacts_[index];
    Track& track = tracks_[index];
    impact.max_depth = std::max(impact.max_depth, e.depth);
    impact.max_force = std::max(impact.max_force, e.force);
    track.last_commit = commits_;
    track.last_time = t;
    track.last_depth = e.depth;
    track.last_rate = e.depth_rate;
    std::copy(e.pos, e.pos + 3, track.last_pos);
    std::copy(e.normal, e.normal + 3, track.last_normal);
  }
}

void EpisodeLog::Close(int index, double separation_velocity) {
  Impact& impact = impacts_[index];
  const Track& track = tracks_[index];
  impact.open = false;
  impact.separation_velocity = separation_velocity;
  const double mean_speed = 0.5 * (-track.last_rate + impact.separation_velocity);
  impact.time_separation =
      mean_speed > 0 ? track.last_time + track.last_depth / mean_speed : track.last_time;
  slot_impact_[track.slot] = -1;
}

// ---------------------------------------------------------------------------

void DissipationLedger::Reset() { *this = DissipationLedger(); }

void DissipationLedger::Commit(double t, const std::vector<PointEvaluation>& points) {
  const double power = DissipatedPower(points);
  const double previous_time = committed_time_;
  if (has_committed_) {
    dissipated_ += 0.5 * (power + committed_power_) * (t - previous_time);
    for (const PointEvaluation& e : points) {
      if (!e.touch) continue;
      const double touch = std::clamp(TouchTime(e, t), previous_time, t);
      dissipated_ += 0.5 * (e.touch_power + e.dissipated_power) * (t - touch) -
                     0.5 * e.dissipated_power * (t - previous_time);
    }
  }
  has_committed_ = true;
  committed_time_ = t;
  committed_power_ = power;
}

double DissipationLedger::Dissipated(double t, const std::vector<PointEvaluation>& points) const {
  double energy = dissipated_;
  if (has_committed_ && t > committed_time_) {
    energy += 0.5 * (DissipatedPower(points) + committed_power_) * (t - committed_time_);
  }
  return energy;
}

}  // namespace contactlaws
