// Copyright contactlaws authors.

#include "contactlaws/contact_model.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>

#include <fmt/format.h>

#include "contactlaws/error.h"
#include "contactlaws/hertz.h"
#include "contactlaws/model_io.h"
#include "contactlaws/tags.h"

namespace contactlaws {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string_view TextName(const mjModel* m, int i) {
  return m->names + m->name_textadr[i];
}

std::string_view TextData(const mjModel* m, int i) {
  const char* data = m->text_data + m->text_adr[i];
  return std::string_view(data, strnlen(data, m->text_size[i]));
}

bool StartsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

uint64_t PairKey(int g1, int g2) {
  if (g1 > g2) std::swap(g1, g2);
  return (static_cast<uint64_t>(g1) << 32) | static_cast<uint32_t>(g2);
}

// Most contact points MuJoCo's narrowphase returns for two geom types.
int MaxContacts(int type1, int type2) {
  if (type1 == mjGEOM_SPHERE || type2 == mjGEOM_SPHERE ||
      type1 == mjGEOM_ELLIPSOID || type2 == mjGEOM_ELLIPSOID) {
    return 1;
  }
  return mjMAXCONPAIR;
}

// Sphere-equivalent radius for the material stiffness (paper eq. 2).
std::optional<double> HertzRadius(const mjModel* m, int g) {
  switch (m->geom_type[g]) {
    case mjGEOM_PLANE: return kInfinity;
    case mjGEOM_SPHERE:
    case mjGEOM_CAPSULE: return m->geom_size[3 * g];
    default: return std::nullopt;
  }
}

bool IsExcluded(const mjModel* m, int b1, int b2) {
  const int s1 = ((b1 + 1) << 16) + b2 + 1;
  const int s2 = ((b2 + 1) << 16) + b1 + 1;
  for (int i = 0; i < m->nexclude; ++i) {
    if (m->exclude_signature[i] == s1 || m->exclude_signature[i] == s2) {
      return true;
    }
  }
  return false;
}

bool IsExplicitPair(const mjModel* m, int g1, int g2) {
  for (int i = 0; i < m->npair; ++i) {
    if ((m->pair_geom1[i] == g1 && m->pair_geom2[i] == g2) ||
        (m->pair_geom1[i] == g2 && m->pair_geom2[i] == g1)) {
      return true;
    }
  }
  return false;
}

// Resolves one tag's geom1/geom2 value to geom ids.
class TagResolver {
 public:
  TagResolver(const mjModel* m, std::string_view source, std::string_view tag)
      : m_(m), source_(source), tag_(tag) {}

  [[noreturn]] void Fail(std::string_view what) const {
    throw Error(fmt::format("{}: {}{}: {}", source_, kPairTagPrefix, tag_, what));
  }

  std::vector<int> Geoms(std::string_view key, const std::string& value,
                         bool* is_group) const {
    std::vector<int> geoms;
    *is_group = StartsWith(value, "group:");
    if (*is_group) {
      std::optional<double> n = ParseNumber(value.substr(6));
      if (!n || *n != std::floor(*n) || *n < 0 || *n >= mjNGROUP) {
        Fail(fmt::format("{}={}: the group must be a whole number in [0, {}]",
                         key, value, mjNGROUP - 1));
      }
      for (int g = 0; g < m_->ngeom; ++g) {
        if (m_->geom_group[g] == static_cast<int>(*n)) geoms.push_back(g);
      }
      if (geoms.empty()) {
        Fail(fmt::format("{}={}: no geom is in group {}", key, value,
                         static_cast<int>(*n)));
      }
    } else {
      int g = mj_name2id(m_, mjOBJ_GEOM, value.c_str());
      if (g < 0) Fail(fmt::format("{}={}: no geom is named '{}'", key, value, value));
      geoms.push_back(g);
    }
    return geoms;
  }

 private:
  const mjModel* m_;
  std::string_view source_;
  std::string_view tag_;
};

}  // namespace

void Drive::Position(double t, double pos[3]) const {
  const double s = amplitude * std::sin(omega * t + phase);
  for (int i = 0; i < 3; ++i) pos[i] = ref[i] + axis[i] * s;
}

void Drive::Velocity(double t, double vel[3]) const {
  const double c = amplitude * omega * std::cos(omega * t + phase);
  for (int i = 0; i < 3; ++i) vel[i] = axis[i] * c;
}

ContactModel::ContactModel(const mjModel* m, std::string source,
                           const Overrides& overrides)
    : model_(m), source_(std::move(source)) {
  body_drive_.assign(m->nbody, -1);
  geom_tagged_.assign(m->ngeom, 0);
  ReadDrives();
  ReadTags(overrides);
}

void ContactModel::ReadDrives() {
  const mjModel* m = model_;
  for (int i = 0; i < m->ntext; ++i) {
    std::string_view name = TextName(m, i);
    if (!StartsWith(name, kDriveTagPrefix)) continue;
    DriveTagSpec spec = ParseDriveTag(source_, name, TextData(m, i));
    auto fail = [&](std::string_view what) {
      throw Error(fmt::format("{}: {}: {}", source_, name, what));
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
    if (body_drive_[drive.body] >= 0) {
      fail(fmt::format("body={}: the body is driven twice", spec.body));
    }
    for (int k = 0; k < 3; ++k) drive.ref[k] = m->body_pos[3 * drive.body + k];
    drive.axis = spec.axis;
    drive.amplitude = spec.amplitude;
    drive.omega = spec.omega;
    drive.phase = spec.phase;
    body_drive_[drive.body] = static_cast<int>(drives_.size());
    drives_.push_back(drive);
  }
}

void ContactModel::ReadTags(const Overrides& overrides) {
  const mjModel* m = model_;
  for (int i = 0; i < m->ntext; ++i) {
    std::string_view name = TextName(m, i);
    if (!StartsWith(name, kPairTagPrefix)) continue;
    PairTagSpec spec = ParsePairTag(source_, name, TextData(m, i));
    TagResolver resolve(m, source_, spec.label);

    // the law and its parameters, overrides first
    LawParams base;
    base.kind = overrides.law ? *overrides.law : *spec.law;
    std::optional<double> restitution =
        overrides.restitution ? overrides.restitution : spec.restitution;
    if (!restitution && base.kind != LawKind::kHertz) {
      resolve.Fail(fmt::format("missing key restitution (law={} needs it)",
                               LawName(base.kind)));
    }
    base.restitution = restitution.value_or(1.0);
    base.exponent = spec.exponent.value_or(1.5);
    base.damping = spec.damping;
    base.min_impact_velocity =
        spec.min_impact_velocity.value_or(kDefaultMinImpactVelocity);
    base.allow_tension = spec.allow_tension.value_or(false);
    const bool materials = spec.youngs1.has_value();
    if (base.kind == LawKind::kKelvinVoigt) {
      // linear: linear_stiffness, or stiffness when the exponent is 1 or absent
      if (spec.linear_stiffness) {
        base.linear_stiffness = *spec.linear_stiffness;
      } else if (spec.stiffness && (!spec.exponent || *spec.exponent == 1.0)) {
        base.linear_stiffness = *spec.stiffness;
      } else {
        resolve.Fail(
            "law=kelvin-voigt needs linear_stiffness (N/m), or stiffness with "
            "exponent 1 or absent");
      }
    } else {
      if (spec.stiffness) {
        base.stiffness = *spec.stiffness;
      } else if (!materials) {
        resolve.Fail(fmt::format(
            "missing key stiffness (or youngs1 poisson1 youngs2 poisson2) for "
            "law={}",
            LawName(base.kind)));
      }
    }

    // the geom pairs the tag covers
    bool group1 = false;
    bool group2 = false;
    std::vector<int> set1 = resolve.Geoms("geom1", spec.geom1, &group1);
    std::vector<int> set2 = resolve.Geoms("geom2", spec.geom2, &group2);
    const bool explicit_pair = !group1 && !group2;
    PairTag tag;
    tag.label = spec.label;
    tag.geom1 = spec.geom1;
    tag.geom2 = spec.geom2;
    tag.law = base.kind;
    tag.restitution = base.restitution;
    const int tag_index = static_cast<int>(tags_.size());

    for (int g1 : set1) {
      for (int g2 : set2) {
        if (g1 == g2) {
          if (explicit_pair) resolve.Fail("geom1 and geom2 are the same geom");
          continue;
        }
        const int b1 = m->geom_bodyid[g1];
        const int b2 = m->geom_bodyid[g2];
        const std::string pair_name =
            fmt::format("({}, {})", ObjectName(m, mjOBJ_GEOM, g1), ObjectName(m, mjOBJ_GEOM, g2));
        // pairs a law cannot act on: an error when named, skipped in a group
        const char* problem = nullptr;
        if (!mjCOLLISIONFUNC[std::min(m->geom_type[g1], m->geom_type[g2])]
                            [std::max(m->geom_type[g1], m->geom_type[g2])]) {
          problem = "MuJoCo has no collision function for these geom types";
        } else if (m->body_weldid[b1] == m->body_weldid[b2]) {
          problem = "the two geoms belong to the same body (or to bodies welded together)";
        } else if (IsExcluded(m, b1, b2)) {
          problem = "the bodies are excluded by <contact><exclude>";
        }
        if (problem) {
          if (explicit_pair) resolve.Fail(fmt::format("{}: {}", pair_name, problem));
          continue;
        }
        if (IsExplicitPair(m, g1, g2)) {
          // the filter hook never sees <pair>: MuJoCo's constraint would stay
          resolve.Fail(fmt::format(
              "{} is also a <contact><pair>, which bypasses the contact filter: "
              "remove one of the two",
              pair_name));
        }
        const uint64_t key = PairKey(g1, g2);
        auto found = pair_index_.find(key);
        if (found != pair_index_.end()) {
          const int other = pairs_[found->second].tag;
          if (other == tag_index) continue;  // group:N with group:N
          resolve.Fail(fmt::format("{} is already tagged by {}{}", pair_name,
                                   kPairTagPrefix, tags_[other].label));
        }

        GeomPair pair;
        const bool swap = m->geom_type[g1] > m->geom_type[g2];
        pair.geom = swap ? std::array<int, 2>{g2, g1} : std::array<int, 2>{g1, g2};
        pair.body = {m->geom_bodyid[pair.geom[0]], m->geom_bodyid[pair.geom[1]]};
        pair.named = {g1, g2};
        pair.tag = tag_index;
        pair.params = base;
        pair.first_slot = slot_count_;
        pair.slots = MaxContacts(m->geom_type[g1], m->geom_type[g2]);
        pair.depth_limit =
            kDivergenceDepthFraction * std::min(GeomSize(m, g1), GeomSize(m, g2));

        // stiffness from materials (paper eqs. 2-3), per pair: radii differ
        if (materials && base.kind != LawKind::kKelvinVoigt) {
          std::optional<double> r1 = HertzRadius(m, g1);
          std::optional<double> r2 = HertzRadius(m, g2);
          if (!r1 || !r2 || (std::isinf(*r1) && std::isinf(*r2))) {
            resolve.Fail(fmt::format(
                "{}: materials (youngs1 ...) need sphere, capsule or plane geoms, "
                "not both planes; give stiffness instead",
                pair_name));
          }
          pair.params.stiffness = HertzSphereStiffness(
              *r1, *r2, MaterialCompliance(*spec.youngs1, *spec.poisson1),
              MaterialCompliance(*spec.youngs2, *spec.poisson2));
        }

        if (std::optional<ParamError> e = ValidateLawParams(pair.params)) {
          resolve.Fail(fmt::format("{}={} {}", e->key, e->value, e->requirement));
        }
        slot_count_ += pair.slots;
        pair_index_.emplace(key, static_cast<int>(pairs_.size()));
        geom_tagged_[g1] = geom_tagged_[g2] = 1;
        tag.pairs.push_back(static_cast<int>(pairs_.size()));
        pairs_.push_back(pair);
      }
    }
    if (tag.pairs.empty()) {
      resolve.Fail(fmt::format(
          "geom1={} geom2={} cover no pair of geoms that can touch", spec.geom1,
          spec.geom2));
    }
    tags_.push_back(std::move(tag));
  }

  // the filter hook, through which the broadphase's proposals come, is never
  // called without collision detection or for dynamic pairs
  if (!tags_.empty() && (m->opt.disableflags & mjDSBL_CONTACT)) {
    throw Error(fmt::format(
        "{}: <flag contact=\"disable\"/> turns off collision detection, so the contact "
        "laws of {} tag(s) would never act: remove the flag",
        source_, tags_.size()));
  }
  if (!tags_.empty() && m->opt.collision == mjCOL_PAIR) {
    throw Error(fmt::format(
        "{}: <option collision=\"predefined\"/> checks only <contact><pair>, which the "
        "tags cannot use, so the contact laws of {} tag(s) would never act: use "
        "collision=\"all\" or \"dynamic\"",
        source_, tags_.size()));
  }
  // MuJoCo would return from mj_passive before calling our hook
  if (!tags_.empty() && (m->opt.disableflags & mjDSBL_PASSIVE)) {
    throw Error(fmt::format(
        "{}: <flag passive=\"disable\"/> turns off mjcb_passive, so the contact "
        "laws of {} tag(s) would never act: remove the flag",
        source_, tags_.size()));
  }
}

int ContactModel::FindPair(int g1, int g2) const {
  if (!geom_tagged_[g1] || !geom_tagged_[g2]) return -1;
  auto found = pair_index_.find(PairKey(g1, g2));
  return found == pair_index_.end() ? -1 : found->second;
}

const Drive* ContactModel::FindDrive(int body) const {
  const int i = body_drive_[body];
  return i < 0 ? nullptr : &drives_[i];
}

double GeomSize(const mjModel* m, int g) {
  const mjtNum* size = m->geom_size + 3 * g;
  switch (m->geom_type[g]) {
    case mjGEOM_PLANE:
    case mjGEOM_HFIELD: return kInfinity;
    case mjGEOM_SPHERE:
    case mjGEOM_CAPSULE: return size[0];
    case mjGEOM_CYLINDER: return std::min(size[0], size[1]);
    case mjGEOM_ELLIPSOID:
    case mjGEOM_BOX: return std::min({size[0], size[1], size[2]});
    default: return m->geom_rbound[g];
  }
}

int DefaultContactFilter(const mjModel* m, int g1, int g2) {
  // contype/conaffinity: at least one direction must match
  if (!(m->geom_contype[g1] & m->geom_conaffinity[g2]) &&
      !(m->geom_contype[g2] & m->geom_conaffinity[g1])) {
    return 1;
  }
  // geoms of the same weld body never collide
  const int weld1 = m->body_weldid[m->geom_bodyid[g1]];
  const int weld2 = m->body_weldid[m->geom_bodyid[g2]];
  if (weld1 == weld2) return 1;
  // parent and child (weld) bodies, unless either is the world or the
  // filterparent flag is disabled
  const int parent1 = m->body_weldid[m->body_parentid[weld1]];
  const int parent2 = m->body_weldid[m->body_parentid[weld2]];
  const bool filter_parent =
      !(m->opt.disableflags & mjDSBL_FILTERPARENT) && weld1 && weld2;
  if (filter_parent && (weld1 == parent2 || weld2 == parent1)) return 1;
  return 0;
}

}  // namespace contactlaws
