// Copyright contactlaws authors.
//
// The tag grammar, parsed without MuJoCo (so it can be tested and fuzzed on
// its own). A tag is an MJCF <custom><text> entry:
//
//   <text name="contactlaw:LABEL"   data="key=value key=value ..."/>
//   <text name="contactdrive:LABEL" data="key=value key=value ..."/>
//
// Values contain no white space. contactlaw keys: see TagKeys (tag_keys.h); contactdrive
// keys: see kDriveKeys. Each key at most once per tag.

#ifndef CONTACTLAWS_SCENE_TAGS_H_
#define CONTACTLAWS_SCENE_TAGS_H_

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "contactlaws/friction.h"
#include "contactlaws/law.h"

namespace contactlaws {

inline constexpr std::string_view kPairTagPrefix = "contactlaw:";
inline constexpr std::string_view kDriveTagPrefix = "contactdrive:";

inline constexpr std::array<std::string_view, 7> kDriveKeys = {
    "body", "motion", "axis", "amplitude", "omega", "phase", "speed"};

namespace internal {

// The friction keys of a contactlaw tag as written; the pair's geoms give
// what is missing (ContactModel).
struct FrictionTagSpec {
  std::optional<FrictionKind> kind;
  std::optional<double> mu, mu_static, mu_kinetic;  // >= 0
  std::optional<double> stribeck_velocity, transition_velocity;  // m/s > 0
  std::optional<double> tangential_stiffness;  // N/m > 0
  std::optional<double> tangential_ratio;      // k_t / (dF_n/dd) > 0
  std::optional<double> tangential_damping;    // N s/m >= 0
  std::optional<double> tangential_damping_ratio;  // [0, 1]
  std::optional<double> bristle_stiffness;     // 1/m > 0
  std::optional<double> bristle_damping;       // s/m >= 0
  std::optional<double> viscous;               // N s/m >= 0
  // the torsional (condim >= 4) and rolling (condim 6) torque caps over F_n,
  // m >= 0: MuJoCo's second and third friction coefficients (lengths)
  std::optional<double> torsional_friction, rolling_friction;
  // the first friction key given (for the warning on a frictionless pair)
  std::string first_key;
};

// A contactlaw tag as written, before it meets a model: numbers parsed and
// range-checked where the range does not depend on the law.
struct PairTagSpec {
  std::string label;  // the tag name after "contactlaw:"
  std::string geom1;  // a geom name, or "group:N"
  std::string geom2;
  std::optional<LawId> law;
  std::optional<double> restitution;
  std::optional<double> stiffness;
  std::optional<double> exponent;
  std::optional<double> linear_stiffness;
  std::optional<double> damping;
  std::optional<double> dissipation;  // s/m, only with a law that reads it
  std::optional<double> min_impact_velocity;
  std::optional<bool> allow_tension;
  // materials: E in Pa (> 0), nu in (-1, 0.5); all four or none
  std::optional<double> youngs1, poisson1, youngs2, poisson2;
  FrictionTagSpec friction;
};

}  // namespace internal

// A contactdrive tag: the body's position is prescribed as
//   motion=sine (default): p(t) = p_ref + axis * amplitude * sin(omega t + phase),
//   motion=linear:         p(t) = p_ref + axis * speed * t,
// p_ref the body's pos in the MJCF, axis a unit vector.
struct DriveTagSpec {
  bool linear = false;
  double speed = 0.0;  // m/s, linear
  std::string label;
  std::string body;
  std::array<double, 3> axis = {0.0, 0.0, 1.0};  // normalized
  double amplitude = 0.0;                        // m
  double omega = 0.0;                            // rad/s
  double phase = 0.0;                            // rad
};

// Parse one tag. name is the full <text> name, data its data; source names the
// file in messages. Throws Error naming source, tag, key and value.
// ParsePairTag is ParsePairWords then CheckPairTag: between the two, a
// ContactModel sets its overrides' keys and values on the tag as written.
namespace internal {
PairTagSpec ParsePairTag(std::string_view source, std::string_view name,
                         std::string_view data);

// The tag's words, each key's value read and checked on its own (its range,
// a law's or friction model's name): no check of the keys together.
PairTagSpec ParsePairWords(std::string_view source, std::string_view name,
                           std::string_view data);

// The word key=value set on spec as a word of the tag's data (it replaces
// the tag's own value of the key): Error "SOURCE: NAME: ..." as for the tag's.
void SetPairWord(std::string_view source, std::string_view name, std::string_view key,
                 std::string_view value, PairTagSpec* spec);

// A numeric key's value set on spec, refused as the tag's own value would be:
// Error "SOURCE: NAME: KEY=VALUE must be ..." (the key's range), or naming a
// key that is not a numeric contactlaw key.
void SetPairNumber(std::string_view source, std::string_view name, std::string_view key,
                   double value, PairTagSpec* spec);

// The checks of the tag's keys together: geom1, geom2 and law given, the
// friction keys that exclude each other, a key the tag's law refuses, the
// materials all four or none and not with stiffness. Throws Error.
void CheckPairTag(std::string_view source, std::string_view name, const PairTagSpec& spec);
}  // namespace internal
DriveTagSpec ParseDriveTag(std::string_view source, std::string_view name,
                           std::string_view data);

// A tag's data with the words key=value of keys set: each replaces the
// word of its key, or is appended when the data has none.
std::string WithKeys(std::string_view data,
                     const std::vector<std::pair<std::string, std::string>>& keys);

// ": did you mean 'hertz'?" for a name close to a law's (letter case aside),
// else "".
std::string LawSuggestion(std::string_view name);

// ": did you mean 'coulomb'?" for a name close to a friction model's (letter
// case aside), else "".
std::string FrictionSuggestion(std::string_view name);

// Refuses (Error naming source and the tag) a <text> name whose prefix is
// within a typo of contactlaw: or contactdrive: (ContactLaw:, contactlaws:),
// which would otherwise leave the pair to MuJoCo without a word.
void CheckTagPrefix(std::string_view source, std::string_view name);

// The candidate closest to word by edit distance, for "did you mean" hints;
// empty when nothing is close.
std::string_view NearestWord(std::string_view word,
                             const std::string_view* candidates, size_t count);

}  // namespace contactlaws

#endif  // CONTACTLAWS_SCENE_TAGS_H_
