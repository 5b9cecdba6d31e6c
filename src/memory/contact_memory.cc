// Copyright contactlaws authors.

#include "memory/contact_memory.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contactlaws {

void PeakForce::Add(double t, double force) {
  peak_ = std::max(peak_, force);
  const double before = time_[1] - time_[0], after = t - time_[1];
  if (count_ == 2 && force_[1] >= force_[0] && force_[1] >= force && after > 0 && before > 0 &&
      std::max(before, after) <= kPeakSpacing * std::min(before, after)) {
    // Newton's form through (t0, f0), (t1, f1), (t, force)
    const double d01 = (force_[1] - force_[0]) / (time_[1] - time_[0]);
    const double d12 = (force - force_[1]) / (t - time_[1]);
    const double c = (d12 - d01) / (t - time_[0]);
    if (c < 0) {
      const double vertex = 0.5 * (time_[0] + time_[1]) - d01 / (2 * c);
      peak_ = std::max(peak_, force_[0] + d01 * (vertex - time_[0]) +
                                  c * (vertex - time_[0]) * (vertex - time_[1]));
    }
  }
  if (count_ == 2) {
    time_[0] = time_[1];
    force_[0] = force_[1];
  }
  time_[count_ == 2 ? 1 : count_] = t;
  force_[count_ == 2 ? 1 : count_] = force;
  count_ = std::min(count_ + 1, 2);
}


namespace {

double Dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// An episode's tangent and normal from its first point (a point episode's
// own point, an impact's first to touch), and that point's slip and spin
// along them.
void OpenTangentialSide(const PointEvaluation& e, Episode* episode) {
  const double speed = std::sqrt(e.slip[0] * e.slip[0] + e.slip[1] * e.slip[1] + e.slip[2] * e.slip[2]);
  for (int i = 0; i < 3; ++i) {
    episode->normal[i] = e.normal[i];
    episode->tangent[i] = speed > 0 ? e.slip[i] / speed : 0.0;
  }
  TangentialSide(e, episode->tangent, episode->normal, &episode->tangential_impact_velocity,
                 &episode->spin_before);
  episode->tangential_separation_velocity = episode->tangential_impact_velocity;
  episode->spin_after = episode->spin_before;
}

}  // namespace

double TouchTime(const PointEvaluation& e, double t, double previous) {
  if (e.at_start) return t;
  const double mean_rate = 0.5 * (e.depth_rate + e.touch_velocity);
  return mean_rate > 0 ? std::clamp(t - e.depth / mean_rate, std::min(previous, t), t) : t;
}

double DepthResolution(const PointEvaluation& e) {
  double size = 0;
  for (int i = 0; i < 3; ++i) {
    size = std::max({size, std::abs(e.pos[i]), std::abs(e.local[0][i]), std::abs(e.local[1][i])});
  }
  return 4 * std::numeric_limits<double>::epsilon() * size;
}

double DissipatedPower(const std::vector<PointEvaluation>& points) {
  double power = 0;
  for (const PointEvaluation& e : points) power += e.dissipated_power + e.friction_power;
  return power;
}

void TangentialSide(const PointEvaluation& e, const double tangent[3], const double normal[3],
                    double* slip, double* spin) {
  // axis = n x t: a ball (body[1]) on a floor (n up, towards the ball) that
  // rolls along t without slipping spins at +v/R about it
  const double axis[3] = {normal[1] * tangent[2] - normal[2] * tangent[1],
                          normal[2] * tangent[0] - normal[0] * tangent[2],
                          normal[0] * tangent[1] - normal[1] * tangent[0]};
  *slip = e.slip[0] * tangent[0] + e.slip[1] * tangent[1] + e.slip[2] * tangent[2];
  *spin = e.spin[0] * axis[0] + e.spin[1] * axis[1] + e.spin[2] * axis[2];
}

// ---------------------------------------------------------------------------

EpisodeLog::EpisodeLog(const std::vector<int>& points_per_pair, int tags)
    : pair_open_(points_per_pair.size()), single_point_(points_per_pair.size()),
      tag_count_(tags, 0) {
  // no allocation while stepping: room for every pair's points
  size_t points = 0, widest = 0;
  for (size_t p = 0; p < points_per_pair.size(); ++p) {
    pair_open_[p].reserve(points_per_pair[p]);
    single_point_[p] = points_per_pair[p] == 1;
    points += points_per_pair[p];
    widest = std::max<size_t>(widest, points_per_pair[p]);
  }
  open_.reserve(points);
  closed_.reserve(points);
  // MatchOpenEpisodes' distances: a pair's points against its open episodes
  distances_.reserve(widest * widest);
}

void EpisodeLog::Reset() {
  for (std::vector<int>& open : pair_open_) open.clear();
  std::fill(tag_count_.begin(), tag_count_.end(), 0);
  open_.clear();
  closed_.clear();
  episodes_.clear();
  tracks_.clear();
  commits_ = 0;
  previous_commit_ = -INFINITY;
}

void EpisodeLog::MatchOpenEpisodes(int pair, const double* local, int count, double tolerance,
                                   int* episode) const {
  const std::vector<int>& open = pair_open_[pair];
  const int episodes = static_cast<int>(std::min<size_t>(open.size(), 64));
  std::fill(episode, episode + count, -1);
  // the distance of a point to an open episode's point: the nearer in the
  // two bodies' frames (a corner is fixed on its box however the box
  // slides, a rolling point moves little on either)
  const auto distance = [&](int i, int k) {
    const Track& track = tracks_[open[k]];
    double nearest = std::numeric_limits<double>::infinity();
    for (const int b : {0, 1}) {
      const double* at = local + 6 * i + 3 * b;
      const double dx = at[0] - track.local[b][0];
      const double dy = at[1] - track.local[b][1];
      const double dz = at[2] - track.local[b][2];
      nearest = std::min(nearest, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
    return nearest;
  };
  // each point's distance to each episode, once
  std::vector<double>& distances = distances_;
  distances.resize(static_cast<size_t>(count) * episodes);
  for (int i = 0; i < count; ++i) {
    for (int k = 0; k < episodes; ++k) {
      distances[static_cast<size_t>(i) * episodes + k] = distance(i, k);
    }
  }
  uint64_t taken = 0;
  for (int matched = 0; matched < std::min(count, episodes); ++matched) {
    // the nearest of the points and episodes left, within tolerance
    int best_point = -1, best_episode = -1;
    double best_distance = tolerance;
    for (int i = 0; i < count; ++i) {
      if (episode[i] >= 0) continue;
      for (int k = 0; k < episodes; ++k) {
        if (taken & (uint64_t{1} << k)) continue;
        const double dist = distances[static_cast<size_t>(i) * episodes + k];
        // (a tie: the first point listed, and its last episode)
        const bool tie = dist == best_distance && (best_point < 0 || best_point == i);
        if (dist < best_distance || tie) {
          best_distance = dist;
          best_point = i;
          best_episode = k;
        }
      }
    }
    if (best_point < 0) break;
    taken |= uint64_t{1} << best_episode;
    episode[best_point] = open[best_episode];
  }
  // one point per pair: the pair's contact, moved
  if (single_point_[pair] && open.size() == 1 && !(taken & 1)) {
    for (int i = 0; i < count; ++i) {
      if (episode[i] < 0) {
        episode[i] = open[0];
        break;
      }
    }
  }
}

void EpisodeLog::Open(double t, const PointEvaluation& e) {
  Episode episode;
  episode.pair = e.pair;
  episode.tag = e.tag;
  episode.index = ++tag_count_[episode.tag];
  episode.impact_velocity = e.touch_velocity;
  episode.touch_v0 = e.impact_velocity;
  episode.time_contact = TouchTime(e, t, previous_commit_);
  OpenTangentialSide(e, &episode);
  const int index = static_cast<int>(episodes_.size());
  episodes_.push_back(episode);
  tracks_.emplace_back();
  tracks_.back().settling = e.at_start;
  open_.push_back(index);
  pair_open_[e.pair].push_back(index);
}

void EpisodeLog::Commit(double t, const std::vector<PointEvaluation>& points) {
  ++commits_;
  for (const PointEvaluation& e : points) {
    // a new point opens its episode, an open one advances
    if (e.episode < 0) Open(t, e);
    const int index = e.episode < 0 ? static_cast<int>(episodes_.size()) - 1 : e.episode;
    Episode& episode = episodes_[index];
    Track& track = tracks_[index];
    episode.max_depth = std::max(episode.max_depth, e.depth);
    episode.resolved = episode.resolved || e.depth > DepthResolution(e);
    track.force.Add(t, e.force);
    episode.max_force = track.force.peak();
    episode.max_approach_velocity = std::max(episode.max_approach_velocity, e.max_approach);
    // a contact there at the start: its first compression is its settling
    if (track.settling) {
      episode.settling_velocity = std::max(episode.settling_velocity, e.depth_rate);
      track.settling = e.depth_rate * kChainFactor >= episode.settling_velocity;
    }
    TangentialSide(e, episode.tangent, episode.normal, &episode.tangential_separation_velocity,
                   &episode.spin_after);
    track.last_commit = commits_;
    track.last_time = t;
    track.last_depth = e.depth;
    track.last_rate = e.depth_rate;
    std::copy(e.pos, e.pos + 3, track.last_pos);
    std::copy(e.normal, e.normal + 3, track.last_normal);
    for (const int b : {0, 1}) std::copy(e.local[b], e.local[b] + 3, track.local[b]);
    track.friction = e.friction_state;
  }
  previous_commit_ = t;
}

void EpisodeLog::Close(int index, double separation_velocity) {
  Episode& episode = episodes_[index];
  const Track& track = tracks_[index];
  episode.open = false;
  episode.separation_velocity = separation_velocity;
  const double mean_speed = 0.5 * (-track.last_rate + episode.separation_velocity);
  episode.time_separation =
      mean_speed > 0 ? track.last_time + track.last_depth / mean_speed : track.last_time;
  std::vector<int>& open = pair_open_[episode.pair];
  open.erase(std::find(open.begin(), open.end(), index));
  closed_.push_back(index);
}

// ---------------------------------------------------------------------------

ImpactLog::ImpactLog(int pairs, int tags)
    : open_(pairs, -1), seen_(pairs, 0), tag_count_(tags, 0), force_(pairs) {}

void ImpactLog::Reset() {
  std::fill(open_.begin(), open_.end(), -1);
  std::fill(tag_count_.begin(), tag_count_.end(), 0);
  impacts_.clear();
  previous_commit_ = -INFINITY;
}

void ImpactLog::Commit(double t, const std::vector<PointEvaluation>& points,
                          const EpisodeLog& episodes) {
  // the points come pair by pair (the hook evaluates the pairs in order)
  for (size_t first = 0; first < points.size();) {
    const int pair = points[first].pair;
    if (open_[pair] < 0) {
      Episode impact;
      impact.pair = pair;
      impact.tag = points[first].tag;
      impact.index = ++tag_count_[impact.tag];
      impact.time_contact = t;
      impact.points = 0;
      OpenTangentialSide(points[first], &impact);
      open_[pair] = static_cast<int>(impacts_.size());
      impacts_.push_back(impact);
      force_[pair] = PeakForce();
    }
    Episode& impact = impacts_[open_[pair]];
    const bool opening = impact.points == 0;
    double force = 0;
    size_t end = first;
    for (; end < points.size() && points[end].pair == pair; ++end) {
      const PointEvaluation& e = points[end];
      force += e.force;
      impact.max_depth = std::max(impact.max_depth, e.depth);
      impact.resolved = impact.resolved || e.depth > DepthResolution(e);
      impact.max_approach_velocity = std::max(impact.max_approach_velocity, e.max_approach);
      // the points that open it: the earliest touch, the fastest approach
      if (opening && e.touch) {
        impact.time_contact =
            std::min(impact.time_contact, TouchTime(e, t, previous_commit_));
        impact.impact_velocity = std::max(impact.impact_velocity, e.touch_velocity);
      }
      if (e.touch) impact.touch_v0 = std::max(impact.touch_v0, e.impact_velocity);
      // (a touch's settling starts at its next commit, as its episode's)
      if (e.episode >= 0) {
        const Episode& point = episodes.episodes()[e.episode];
        impact.settling_velocity =
            std::max(impact.settling_velocity, point.settling_velocity);
        if (point.chained()) impact.points_chained = true;
      }
    }
    force_[pair].Add(t, force);
    impact.max_force = force_[pair].peak();
    TangentialSide(points[first], impact.tangent, impact.normal,
                   &impact.tangential_separation_velocity, &impact.spin_after);
    impact.points = std::max(impact.points, static_cast<int>(end - first));
    seen_[pair] = 1;
    first = end;
  }
  // a pair with no point left: its impact ends with its last points
  for (size_t pair = 0; pair < open_.size(); ++pair) {
    if (open_[pair] >= 0 && !seen_[pair]) {
      Episode& impact = impacts_[open_[pair]];
      impact.open = false;
      impact.time_separation = -INFINITY;
      impact.separation_velocity = -INFINITY;
      for (const int index : episodes.closed()) {
        const Episode& point = episodes.episodes()[index];
        if (point.pair != static_cast<int>(pair)) continue;
        impact.time_separation = std::max(impact.time_separation, point.time_separation);
        impact.separation_velocity =
            std::max(impact.separation_velocity, point.separation_velocity);
      }
      // (its last points closed in this commit: the episodes' own close)
      const int closed = open_[pair];
      open_[pair] = -1;
      if (!impact.resolved) Drop(closed);
    }
    seen_[pair] = 0;
  }
  previous_commit_ = t;
}

void ImpactLog::Drop(int index) {
  const int tag = impacts_[index].tag;
  for (size_t k = index + 1; k < impacts_.size(); ++k) {
    if (impacts_[k].tag == tag) --impacts_[k].index;
  }
  --tag_count_[tag];
  impacts_.erase(impacts_.begin() + index);
  for (int& open : open_) {
    if (open > index) --open;
  }
}

// ---------------------------------------------------------------------------

void DissipationLedger::Reset() { *this = DissipationLedger(); }

void DissipationLedger::Commit(double t, const std::vector<PointEvaluation>& points,
                               Booking booking) {
  const double power = DissipatedPower(points);
  const double previous_time = committed_time_;
  const double h = t - previous_time;
  if (has_committed_) {
    dissipated_ += 0.5 * (power + committed_power_) * h;
    for (const PointEvaluation& e : points) {
      if (!e.touch) continue;
      const double touch = TouchTime(e, t, previous_time);
      dissipated_ += 0.5 * (e.touch_power + e.dissipated_power) * (t - touch) -
                     0.5 * e.dissipated_power * h;
    }
    // kHeldForce (held_ filled at the last commit): the end's half is the
    // start's forces at the end's rates, for the points in contact at both
    if (!held_.empty()) {
      for (const PointEvaluation& e : points) {
        if (e.touch || e.episode < 0) continue;
        const auto held = std::lower_bound(
            held_.begin(), held_.end(), e.episode,
            [](const HeldForce& f, int episode) { return f.episode < episode; });
        if (held == held_.end() || held->episode != e.episode) continue;
        const double held_power = held->damping * e.depth_rate -
                                  Dot3(held->friction, e.slip) - Dot3(held->torque, e.spin);
        dissipated_ += 0.5 * h * (held_power - e.dissipated_power - e.friction_power);
      }
    }
  }
  // the deferred quadratures, each less its end's half at its episode's
  // point (by episode, as held_ below: a pile's hundreds of points)
  if (!deferred_.empty()) {
    std::sort(deferred_.begin(), deferred_.end(),
              [](const Deferred& a, const Deferred& b) { return a.episode < b.episode; });
    for (const Deferred& deferred : deferred_) dissipated_ += deferred.energy;
    for (const PointEvaluation& e : points) {
      if (e.touch || e.episode < 0) continue;
      const auto found = std::lower_bound(
          deferred_.begin(), deferred_.end(), e.episode,
          [](const Deferred& f, int episode) { return f.episode < episode; });
      if (found != deferred_.end() && found->episode == e.episode) {
        dissipated_ -= found->half_step * e.dissipated_power;
      }
    }
    deferred_.clear();
  }
  held_.clear();
  if (booking == Booking::kHeldForce) {
    for (const PointEvaluation& e : points) {
      if (e.episode < 0) continue;
      // the damping force is the power over the rate (0 at d' = 0, where
      // the laws' damping force is 0)
      HeldForce held{e.episode, e.depth_rate != 0 ? e.dissipated_power / e.depth_rate : 0.0,
                     {e.friction[0], e.friction[1], e.friction[2]},
                     {e.friction_torque[0], e.friction_torque[1], e.friction_torque[2]}};
      held_.push_back(held);
    }
    // by episode, for the next commit's lookups (a pile of 216 points)
    std::sort(held_.begin(), held_.end(),
              [](const HeldForce& a, const HeldForce& b) { return a.episode < b.episode; });
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
  // what friction took from the bodies and its springs still hold is not lost
  for (const PointEvaluation& e : points) energy -= e.friction_energy;
  return energy;
}

}  // namespace contactlaws
