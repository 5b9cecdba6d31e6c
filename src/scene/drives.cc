// Copyright contactlaws authors.
//
// The driven bodies of a ContactModel: the contactdrive: tags read and
// checked, and a drive's prescribed motion.

#include "contactlaws/contact_model.h"

#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "scene/contact_model_reader.h"
#include "scene/parsed_tags.h"

namespace contactlaws {

void Drive::Position(double t, double pos[3]) const {
  const double s =
      motion == Motion::kLinear ? speed * t : amplitude * std::sin(omega * t + phase);
  for (int i = 0; i < 3; ++i) pos[i] = ref[i] + axis[i] * s;
}

void Drive::Velocity(double t, double vel[3]) const {
  const double c =
      motion == Motion::kLinear ? speed : amplitude * omega * std::cos(omega * t + phase);
  for (int i = 0; i < 3; ++i) vel[i] = axis[i] * c;
}

namespace internal {

void ContactModelReader::ReadDrives(const ParsedTags& tags) {
  const mjModel* m = cm_.model_;
  for (const auto& tag : tags.drives()) {
    if (!tag.error.empty()) throw Error(tag.error);
    const std::string_view name = tag.name;
    const DriveTagSpec& spec = tag.spec;
    auto fail = [&](std::string_view what) {
      throw Error(fmt::format("{}: {}: {}", cm_.source_, name, what));
    };
    Drive drive;
    drive.label = spec.label;
    drive.body = mj_name2id(m, mjOBJ_BODY, spec.body.c_str());
    if (drive.body < 0) {
      fail(fmt::format("body={}: no body is named '{}'", spec.body, spec.body));
    }
    drive.mocap = m->body_mocapid[drive.body];
    if (drive.mocap < 0) {
      fail(fmt::format("body={}: a driven body must be declared mocap=\"true\"",
                       spec.body));
    }
    if (cm_.body_drive_[drive.body] >= 0) {
      fail(fmt::format("body={}: the body is driven twice", spec.body));
    }
    for (int k = 0; k < 3; ++k) drive.ref[k] = m->body_pos[3 * drive.body + k];
    drive.axis = spec.axis;
    drive.amplitude = spec.amplitude;
    drive.omega = spec.omega;
    drive.phase = spec.phase;
    drive.motion = spec.linear ? Drive::Motion::kLinear : Drive::Motion::kSine;
    drive.speed = spec.speed;
    cm_.body_drive_[drive.body] = static_cast<int>(cm_.drives_.size());
    cm_.drives_.push_back(drive);
  }
}

}  // namespace internal

}  // namespace contactlaws
