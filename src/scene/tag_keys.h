// Copyright contactlaws authors.
//
// The keys of a contactlaw tag: one row per key, read by the tag parser
// (its values, ranges and messages), by the fit (which keys are numbers,
// which laws and friction models read each: `fit --params`) and by the
// overrides (Overrides::keys, parsed as the tag's own words; Overrides::values,
// a fit's numbers, set on the tag by the same per-key rule: range, field,
// message, tags.h's SetPairNumber). Adding a key is one row here, its field
// in PairTagSpec (tags.h) and a test.

#ifndef CONTACTLAWS_SCENE_TAG_KEYS_H_
#define CONTACTLAWS_SCENE_TAG_KEYS_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contactlaws/friction.h"
#include "contactlaws/law.h"
#include "laws/param_range.h"
#include "scene/tags.h"

namespace contactlaws {

// What a key's value is.
enum class TagValue {
  kGeom,      // a geom name or group:N
  kLaw,       // a law's name (ParseLawName)
  kFriction,  // a friction model's name (ParseFrictionName)
  kSwitch,    // true, false, 1 or 0
  kNumber,    // a finite number (ParseNumber) in the key's range
};

// The tags that read a key, by their law and friction model.
enum class TagReaders {
  kEvery,
  kRestitutionLaws,   // ReadsRestitution
  kDissipationLaws,   // ReadsDissipation
  kHertzFamily,       // every law but the linear one
  kLinearLaw,         // kelvin-voigt
  kAnyFriction,       // every friction model but none
  kStickSpring,       // coulomb and stribeck
  kRegularized,
  kStribeckCurve,     // stribeck and lugre
  kLuGre,
};

// One key of a contactlaw tag.
struct TagKey {
  std::string_view name;
  TagValue value;
  const ParamRange* range;  // kNumber: the values accepted
  std::string_view unit;    // kNumber: said in the range's message, "" for none
  TagReaders readers;
  // given to a tag whose law does not read it: refused (else ignored, as
  // Hertz ignores the restitution)
  bool refused_unread;
  // the field of PairTagSpec it sets: one of these
  std::string internal::PairTagSpec::*text;
  std::optional<double> internal::PairTagSpec::*number;
  std::optional<double> internal::FrictionTagSpec::*friction_number;
  // the value a pair takes when the tag does not give it; nullopt when it is
  // required or comes from the model (the geoms' friction, the materials)
  std::optional<double> fallback;

  // A key of the friction model's (friction.h), not of the law's.
  bool friction_side() const { return value == TagValue::kFriction || friction_number; }
};

// Every key (NearestWord's hints take the first of equally near names).
const std::vector<TagKey>& TagKeys();
// Their names, for "did you mean" hints.
const std::vector<std::string_view>& TagKeyNames();
// The row of a key; nullptr for an unknown key.
const TagKey* FindTagKey(std::string_view name);

// Whether a tag with this law and friction model reads the key's value.
bool Reads(const TagKey& key, LawId law, FrictionKind friction);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SCENE_TAG_KEYS_H_
