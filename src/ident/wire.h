// Copyright contactlaws authors.
//
// Values as bytes and back, for WorkSpread's exchange between the processes
// of a job: cereal's binary archive (each field in its native form, so a
// double arrives bit for bit; the ranks of a job share one architecture).
// The one serialiser of the library and the program: each type sent names
// its fields once, in a serialize function beside the others below (or, for
// a type with private members, a serialize member). Internal: no installed
// header includes it.

#ifndef CONTACTLAWS_IDENT_WIRE_H_
#define CONTACTLAWS_IDENT_WIRE_H_

#include <sstream>
#include <string>
#include <utility>

#include <cereal/archives/binary.hpp>
#include <cereal/types/common.hpp>
#include <cereal/types/optional.hpp>
#include <cereal/types/string.hpp>
#include <cereal/types/utility.hpp>
#include <cereal/types/vector.hpp>

#include "contactlaws/impact.h"
#include "contactlaws/replay.h"
#include "sim/summary.h"

namespace contactlaws {

// The fields of the types the ranks exchange. A field added to one of these
// structs must be added here too: the size checks below fail until it is
// (each struct's size on x86-64 and arm64, padding included).

template <typename Archive>
void serialize(Archive& archive, Score& s) {
  static_assert(sizeof(Score) == 48, "Score changed: name its new field here");
  archive(s.samples, s.e_q, s.position_rms, s.angle_rms, s.joint_rms, s.weighted);
}

template <typename Archive>
void serialize(Archive& archive, ReplayedTrajectory& r) {
  archive(r.status, r.start, r.score, r.diverged_at, r.settled_bodies, r.settled_distance, r.last,
          r.simulated);
}

template <typename Archive>
void serialize(Archive& archive, Episode& e) {
  static_assert(sizeof(Episode) == 184, "Episode changed: name its new field here");
  archive(e.tag, e.pair, e.index, e.points, e.time_contact, e.impact_velocity, e.open,
          e.time_separation, e.separation_velocity, e.max_depth, e.max_force,
          e.max_approach_velocity, e.touch_v0, e.points_chained, e.resolved, e.settling_velocity,
          e.tangential_impact_velocity, e.tangential_separation_velocity, e.spin_before,
          e.spin_after, e.tangent, e.normal);
}

template <typename Archive>
void serialize(Archive& archive, RunSummary& s) {
  static_assert(sizeof(RunSummary) == 88,
                "RunSummary changed: name its new field here");
  archive(s.impacts, s.restitution_post, s.impact_velocity, s.contact_duration, s.max_depth,
          s.max_force, s.time_to_rest);
}

namespace internal {

// value's fields as bytes (Read's inverse).
template <typename T>
std::string Written(const T& value) {
  std::ostringstream bytes(std::ios::binary);
  {
    cereal::BinaryOutputArchive archive(bytes);
    archive(value);
  }
  return std::move(bytes).str();
}

// A T from what Written gave; throws cereal::Exception on bytes cut short.
template <typename T>
T Read(const std::string& bytes) {
  std::istringstream in(bytes, std::ios::binary);
  cereal::BinaryInputArchive archive(in);
  T value;
  archive(value);
  return value;
}

}  // namespace internal
}  // namespace contactlaws

#endif  // CONTACTLAWS_IDENT_WIRE_H_
