// Copyright contactlaws authors.

#include "contactlaws/contact_model.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string_view>

#include <fmt/format.h>

#include "contactlaws/law.h"
#include "scene/contact_model_reader.h"
#include "scene/model_queries.h"
#include "scene/number.h"
#include "scene/pair_friction.h"
#include "scene/pair_trust.h"
#include "scene/parsed_tags.h"
#include "scene/tags.h"

namespace contactlaws {

namespace {

bool StartsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

uint64_t PairKey(int g1, int g2) {
  if (g1 > g2) std::swap(g1, g2);
  return (static_cast<uint64_t>(g1) << 32) | static_cast<uint32_t>(g2);
}

}  // namespace

namespace internal {

// Resolves one tag's geom1/geom2 value to geom ids.
class TagResolver {
 public:
  TagResolver(const mjModel* m, std::string_view source, std::string_view tag)
      : m_(m), source_(source), tag_(tag) {}

  // "SOURCE: contactlaw:TAG: WHAT"
  std::string Message(std::string_view what) const {
    return fmt::format("{}: {}{}: {}", source_, kPairTagPrefix, tag_, what);
  }

  [[noreturn]] void Fail(std::string_view what) const { throw Error(Message(what)); }

  std::vector<int> Geoms(std::string_view key, const std::string& value,
                         bool* is_group) const {
    std::vector<int> geoms;
    *is_group = StartsWith(value, "group:");
    if (*is_group) {
      const std::optional<long> n = ParseWholeNumber(value.substr(6), 0, mjNGROUP - 1);
      if (!n) {
        Fail(fmt::format("{}={}: the group must be a whole number in [0, {}]",
                         key, value, mjNGROUP - 1));
      }
      for (int g = 0; g < m_->ngeom; ++g) {
        if (m_->geom_group[g] == *n) geoms.push_back(g);
      }
      if (geoms.empty()) {
        Fail(fmt::format("{}={}: no geom is in group {}", key, value, *n));
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

}  // namespace internal

using internal::CheckPairTag;
using internal::PairTagSpec;
using internal::SetPairNumber;
using internal::SetPairWord;
using internal::TagResolver;

ContactModel::ContactModel(const mjModel* m, std::string source,
                           const Overrides& overrides)
    : ContactModel(m, source, overrides, internal::ParsedTags(m, source)) {}

ContactModel::ContactModel(const mjModel* m, std::string source, const Overrides& overrides,
                           const internal::ParsedTags& tags)
    : model_(m), source_(std::move(source)) {
  body_drive_.assign(m->nbody, -1);
  geom_tagged_.assign(m->ngeom, 0);
  overrides_ = overrides;
  if (!tags.prefix_error().empty()) throw Error(tags.prefix_error());
  internal::ContactModelReader reader(this);
  reader.ReadDrives(tags);
  reader.ReadTags(tags, overrides);
}

namespace {

// The law of a tag with the overrides applied, and every parameter that does
// not depend on the pair (materials give the stiffness per pair).
LawParams ResolveLaw(const PairTagSpec& spec, const Overrides& overrides,
                     const TagResolver& resolve) {
  LawParams base;
  base.law = overrides.law ? *overrides.law : *spec.law;
  const std::optional<double> restitution =
      overrides.restitution ? overrides.restitution : spec.restitution;
  if (!restitution && ReadsRestitution(base.law)) {
    resolve.Fail(fmt::format("missing key restitution (law={} needs it)", LawName(base.law)));
  }
  // the dissipation of a law that reads it: the override, else the tag's
  if (ReadsDissipation(base.law)) {
    base.dissipation = overrides.dissipation ? overrides.dissipation : spec.dissipation;
    if (!base.dissipation) {
      // a law given by an override (--law, --laws) cannot find it in the tag
      // of another law: say where it can come from
      const std::string what =
          fmt::format("missing key dissipation (law={} takes: {})", LawName(base.law),
                      Law(base.law).parameters);
      if (!overrides.law || *overrides.law == *spec.law) resolve.Fail(what);
      throw OptionError(resolve.Message(fmt::format("{}; the tag's law={} does not read it: "
                                                    "give the dissipation override ({})",
                                                    what, LawName(*spec.law), OptionError::kMark)),
                        {{OptionError::Form::kName, "dissipation", ""}});
    }
  }
  base.restitution = restitution.value_or(1.0);
  // what the tag does not give keeps LawParams' default (TagKey::fallback)
  if (spec.exponent) base.exponent = *spec.exponent;
  base.damping = spec.damping;
  if (spec.min_impact_velocity) base.min_impact_velocity = *spec.min_impact_velocity;
  if (spec.allow_tension) base.allow_tension = *spec.allow_tension;
  const bool materials = spec.youngs1.has_value();
  if (Law(base.law).family == LawFamily::kLinear) {
    // linear: linear_stiffness, or stiffness when the exponent is 1 or absent
    if (spec.linear_stiffness) {
      base.linear_stiffness = *spec.linear_stiffness;
    } else if (spec.stiffness && (!spec.exponent || *spec.exponent == 1.0)) {
      base.linear_stiffness = *spec.stiffness;
    } else {
      resolve.Fail(fmt::format("law={} needs linear_stiffness (N/m), or stiffness with "
                               "exponent 1 or absent",
                               LawName(base.law)));
    }
  } else if (spec.stiffness) {
    base.stiffness = *spec.stiffness;
  } else if (!materials) {
    resolve.Fail(fmt::format(
        "missing key stiffness (or youngs1 poisson1 youngs2 poisson2) for law={}",
        LawName(base.law)));
  }
  return base;
}

// Why the law cannot act on geoms g1, g2, or nullptr.
const char* PairProblem(const mjModel* m, int g1, int g2) {
  const int b1 = m->geom_bodyid[g1];
  const int b2 = m->geom_bodyid[g2];
  if (NarrowphaseOf(m, g1, g2) == Narrowphase::kNone) {
    return "MuJoCo has no collision function for these geom types";
  }
  if (m->body_weldid[b1] == m->body_weldid[b2]) {
    return "the two geoms belong to the same body (or to bodies welded together)";
  }
  if (IsExcluded(m, b1, b2)) return "the bodies are excluded by <contact><exclude>";
  return nullptr;
}

// The stiffness of two materials for the pair's radii (paper eqs. 2-3).
double MaterialStiffness(const mjModel* m, int g1, int g2, const PairTagSpec& spec,
                         const std::string& pair_name, const TagResolver& resolve) {
  const std::optional<double> r1 = HertzRadius(m, g1);
  const std::optional<double> r2 = HertzRadius(m, g2);
  // Hertz's formula takes the radii of curvature where the surfaces touch: a
  // sphere's or capsule's radius, a plane's infinity
  for (const int g : {g1, g2}) {
    if (HertzRadius(m, g)) continue;
    resolve.Fail(fmt::format(
        "{}: materials (youngs1 ...) give K through Hertz's formula from the radii of "
        "curvature at the contact, and the {} {} has none (corners, edges and flat faces: "
        "spheres, capsules and planes have one): give stiffness (N/m^n) instead",
        pair_name, GeomTypeName(m->geom_type[g]), ObjectName(m, mjOBJ_GEOM, g)));
  }
  if (std::isinf(*r1) && std::isinf(*r2)) {
    resolve.Fail(fmt::format(
        "{}: materials (youngs1 ...) need a curved geom: two planes have no radius of "
        "curvature for Hertz's formula; give stiffness (N/m^n) instead",
        pair_name));
  }
  return HertzSphereStiffness(*r1, *r2, MaterialCompliance(*spec.youngs1, *spec.poisson1),
                              MaterialCompliance(*spec.youngs2, *spec.poisson2));
}

// Refuses a model whose flags keep the hooks from ever acting.
void CheckFlags(const mjModel* m, const std::string& source, size_t tags) {
  if (tags == 0) return;
  // the filter hook, through which the broadphase's proposals come, is never
  // called without collision detection or for dynamic pairs
  if (m->opt.disableflags & mjDSBL_CONTACT) {
    throw Error(fmt::format(
        "{}: <flag contact=\"disable\"/> turns off collision detection, so the contact "
        "laws of {} tag(s) would never act: remove the flag",
        source, tags));
  }
  if (m->opt.collision == mjCOL_PAIR) {
    throw Error(fmt::format(
        "{}: <option collision=\"predefined\"/> checks only <contact><pair>, which the "
        "tags cannot use, so the contact laws of {} tag(s) would never act: use "
        "collision=\"all\" or \"dynamic\"",
        source, tags));
  }
  // MuJoCo would return from mj_passive before calling our hook
  if (m->opt.disableflags & mjDSBL_PASSIVE) {
    throw Error(fmt::format(
        "{}: <flag passive=\"disable\"/> turns off mjcb_passive, so the contact "
        "laws of {} tag(s) would never act: remove the flag",
        source, tags));
  }
}

}  // namespace

void internal::ContactModelReader::ReadTags(const ParsedTags& tags,
                                           const Overrides& overrides) {
  const mjModel* m = cm_.model_;
  const bool set = !overrides.keys.empty() || !overrides.values.empty();
  for (const auto& written : tags.pairs()) {
    if (!written.error.empty()) throw Error(written.error);
    // the tag's words, then the keys and values set, read under the law
    // that overrides the tag's, if any: a key that law reads (dissipation)
    // is then not refused as the tag's law's
    PairTagSpec spec = written.spec;
    for (const auto& [key, value] : overrides.keys) {
      SetPairWord(cm_.source_, written.name, key, value, &spec);
    }
    for (const KeyValue& v : overrides.values) {
      SetPairNumber(cm_.source_, written.name, v.key, v.value, &spec);
    }
    if (set && overrides.law) spec.law = overrides.law;
    CheckPairTag(cm_.source_, written.name, spec);
    const TagResolver resolve(m, cm_.source_, spec.label);
    const LawParams base = ResolveLaw(spec, overrides, resolve);

    PairTag tag;
    tag.label = spec.label;
    tag.geom1 = spec.geom1;
    tag.geom2 = spec.geom2;
    tag.law = base.law;
    tag.restitution = base.restitution;
    AddPairs(spec, base, resolve, &tag);
    cm_.tags_.push_back(std::move(tag));
  }
  CheckFlags(m, cm_.source_, cm_.tags_.size());
}

void internal::ContactModelReader::AddPairs(const PairTagSpec& spec, const LawParams& base,
                                           const TagResolver& resolve, PairTag* tag) {
  const mjModel* m = cm_.model_;
  bool group1 = false;
  bool group2 = false;
  const std::vector<int> set1 = resolve.Geoms("geom1", spec.geom1, &group1);
  const std::vector<int> set2 = resolve.Geoms("geom2", spec.geom2, &group2);
  const bool explicit_pair = !group1 && !group2;
  const int tag_index = static_cast<int>(cm_.tags_.size());
  std::vector<int> warned_types;
  for (const int g1 : set1) {
    for (const int g2 : set2) {
      if (g1 == g2) {
        if (explicit_pair) resolve.Fail("geom1 and geom2 are the same geom");
        continue;
      }
      const std::string pair_name =
          fmt::format("({}, {})", ObjectName(m, mjOBJ_GEOM, g1), ObjectName(m, mjOBJ_GEOM, g2));
      // pairs a law cannot act on: an error when named, skipped in a group
      if (const char* problem = PairProblem(m, g1, g2)) {
        if (explicit_pair) resolve.Fail(fmt::format("{}: {}", pair_name, problem));
        continue;
      }
      CheckDepth(g1, g2, pair_name, resolve, &warned_types);
      if (IsExplicitPair(m, g1, g2)) {
        // the filter hook never sees <pair>: MuJoCo's constraint would stay
        resolve.Fail(fmt::format(
            "{} is also a <contact><pair>, which bypasses the contact filter: remove one of "
            "the two",
            pair_name));
      }
      const uint64_t key = PairKey(g1, g2);
      if (const auto found = cm_.pair_index_.find(key); found != cm_.pair_index_.end()) {
        const int other = cm_.pairs_[found->second].tag;
        if (other == tag_index) continue;  // group:N with group:N
        resolve.Fail(fmt::format("{} is already tagged by {}{}", pair_name, kPairTagPrefix,
                                 cm_.tags_[other].label));
      }

      GeomPair pair;
      pair.geom = CollisionOrder(m, g1, g2);
      pair.body = {m->geom_bodyid[pair.geom[0]], m->geom_bodyid[pair.geom[1]]};
      pair.named = {g1, g2};
      pair.tag = tag_index;
      pair.params = base;
      pair.slots = MaxContacts(m, g1, g2);
      const double size = std::min(GeomSize(m, g1), GeomSize(m, g2));
      pair.depth_limit = kDivergenceDepthFraction * size;
      pair.identity_tolerance = kContactIdentityFraction * size;
      // stiffness from materials, per pair: radii differ
      if (spec.youngs1 && Law(base.law).family != LawFamily::kLinear) {
        pair.params.stiffness = MaterialStiffness(m, g1, g2, spec, pair_name, resolve);
      }
      if (const std::optional<ParamError> e = ValidateLawParams(pair.params)) {
        resolve.Fail(fmt::format("{}={} {}", e->key, e->value, e->requirement));
      }
      ResolveLawParams(&pair.params);
      AddFriction(g1, g2, spec, pair_name, resolve, &pair);

      cm_.slot_count_ += pair.slots;
      cm_.pair_index_.emplace(key, static_cast<int>(cm_.pairs_.size()));
      cm_.geom_tagged_[g1] = cm_.geom_tagged_[g2] = 1;
      tag->pairs.push_back(static_cast<int>(cm_.pairs_.size()));
      cm_.pairs_.push_back(pair);
    }
  }
  if (tag->pairs.empty()) {
    resolve.Fail(fmt::format("geom1={} geom2={} cover no pair of geoms that can touch",
                             spec.geom1, spec.geom2));
  }
}

void internal::ContactModelReader::AddFriction(int g1, int g2, const PairTagSpec& spec,
                                              const std::string& pair_name,
                                              const TagResolver& resolve, GeomPair* pair) {
  const PairFriction friction = ResolvePairFriction(cm_.model_, g1, g2, spec, cm_.overrides_);
  if (!friction.error.empty()) resolve.Fail(fmt::format("{}: {}", pair_name, friction.error));
  if (friction.ignored_key) {
    cm_.warnings_.push_back(resolve.Message(fmt::format(
        "{}: {} is not read: the pair is frictionless (condim 1, as in MuJoCo)", pair_name,
        *friction.ignored_key)));
  }
  if (friction.unread_cap) {
    cm_.warnings_.push_back(
        resolve.Message(fmt::format("{}: {}", pair_name, *friction.unread_cap)));
  }
  pair->friction = friction.params;
  pair->condim = friction.condim;
  pair->friction_mass = PairFrictionMass(cm_.model_, pair->body[0], pair->body[1]);
  pair->friction_inertia = PairFrictionMass(cm_.model_, pair->body[0], pair->body[1], true);
}

void internal::ContactModelReader::CheckDepth(int g1, int g2, const std::string& pair_name,
                                             const TagResolver& resolve,
                                             std::vector<int>* warned_types) {
  const int t1 = std::min(cm_.model_->geom_type[g1], cm_.model_->geom_type[g2]);
  const int t2 = std::max(cm_.model_->geom_type[g1], cm_.model_->geom_type[g2]);
  DepthVerdict verdict = JudgeDepth(t1, t2);
  // box-mesh and mesh-mesh within the polytope caps are contactlaws' own
  if (NarrowphaseOf(cm_.model_, g1, g2) == Narrowphase::kPolytope) {
    verdict = {DepthTrust::kComputed, ""};
  }
  // refused in a group too: skipped, the pair would fall back to MuJoCo's
  // own contact unsaid
  if (verdict.trust == DepthTrust::kRefused) {
    resolve.Fail(fmt::format("{}: {}", pair_name, verdict.reason));
  }
  // warned once per tag and pair type, naming its first pair
  const int type = t1 * mjNGEOMTYPES + t2;
  if (verdict.trust != DepthTrust::kWarned ||
      std::find(warned_types->begin(), warned_types->end(), type) != warned_types->end()) {
    return;
  }
  warned_types->push_back(type);
  cm_.warnings_.push_back(resolve.Message(fmt::format("{}: {}", pair_name, verdict.reason)));
}

int ContactModel::FindPair(int g1, int g2) const {
  if (!geom_tagged_[g1] || !geom_tagged_[g2]) return -1;
  auto found = pair_index_.find(PairKey(g1, g2));
  return found == pair_index_.end() ? -1 : found->second;
}

}  // namespace contactlaws
