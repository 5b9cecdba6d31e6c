// Copyright contactlaws authors.
//
// The table of contactlaw tag keys: each row's range refuses what is outside
// it with the row's message, each accepted value lands in the row's field,
// each key is read by some law and friction model, and docs/tags.md lists
// every key.

#include "scene/tag_keys.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contactlaws/contact_model.h"
#include "scene/pair_tag_error.h"

namespace contactlaws {
namespace {

using internal::PairTagSpec;
using internal::ParsePairTag;

// A tag that reads key at value: a law that reads it, and what the key
// needs beside it (the other materials, else a stiffness).
std::string TagWith(const TagKey& key, const std::string& value) {
  const char* law = key.refused_unread ? "hunt-crossley-constant" : "hertz";
  std::string data = fmt::format("geom1=a geom2=b law={} {}={}", law, key.name, value);
  const std::string_view materials[] = {"youngs1", "poisson1", "youngs2", "poisson2"};
  if (std::find(std::begin(materials), std::end(materials), key.name) != std::end(materials)) {
    for (const std::string_view other : materials) {
      if (other != key.name) data += fmt::format(" {}={}", other, other[0] == 'y' ? "2e11" : "0.3");
    }
  } else if (key.name != "stiffness") {
    data += " stiffness=1e8";
  }
  return data;
}

TEST(TagKeysTest, EveryNumberOutsideItsRangeIsRefusedNamingKeyValueAndRange) {
  for (const TagKey& key : TagKeys()) {
    if (key.value != TagValue::kNumber) continue;
    const ParamRange& range = *key.range;
    // the lower bound when it is excluded, else just below it
    const double below = range.lo_open ? range.lo : range.lo - 1;
    const std::string value = fmt::format("{}", below);
    EXPECT_EQ(PairTagError(TagWith(key, value)),
              fmt::format("s.xml: contactlaw:t: {}={} {}", key.name, value,
                          range.Requirement(key.unit)));
  }
}

TEST(TagKeysTest, EveryNumberInsideItsRangeLandsInItsField) {
  for (const TagKey& key : TagKeys()) {
    if (key.value != TagValue::kNumber) continue;
    const ParamRange& range = *key.range;
    const double inside = std::isinf(range.hi) ? range.lo + 1 : (range.lo + range.hi) / 2;
    const PairTagSpec spec =
        ParsePairTag("s.xml", "contactlaw:t", TagWith(key, fmt::format("{}", inside)));
    const std::optional<double> read = key.number ? spec.*key.number
                                                  : spec.friction.*key.friction_number;
    EXPECT_EQ(read, inside) << key.name;
    // a friction key is the first friction key given (the warning on a
    // frictionless pair names it)
    EXPECT_EQ(spec.friction.first_key, key.friction_side() ? key.name : "") << key.name;
  }
}

TEST(TagKeysTest, EachRowSetsOneField) {
  for (const TagKey& key : TagKeys()) {
    const int fields = (key.text != nullptr) + (key.number != nullptr) +
                       (key.friction_number != nullptr);
    EXPECT_EQ(fields, key.value == TagValue::kNumber || key.value == TagValue::kGeom ? 1 : 0)
        << key.name;
    EXPECT_EQ(key.range != nullptr, key.value == TagValue::kNumber) << key.name;
    EXPECT_EQ(FindTagKey(key.name), &key);
  }
  EXPECT_EQ(FindTagKey("stifness"), nullptr);
}

TEST(TagKeysTest, EveryKeyIsReadBySomeLawAndFrictionModel) {
  for (const TagKey& key : TagKeys()) {
    bool read = false;
    for (const LawId law : AllLaws()) {
      for (const FrictionInfo& friction : FrictionModels()) {
        read = read || Reads(key, law, friction.kind);
      }
    }
    EXPECT_TRUE(read) << key.name;
  }
  const LawId hertz = *ParseLawName("hertz");
  const LawId constant = *ParseLawName("hunt-crossley-constant");
  const LawId kelvin = *ParseLawName("kelvin-voigt");
  EXPECT_FALSE(Reads(*FindTagKey("restitution"), hertz, FrictionKind::kCoulomb));
  EXPECT_TRUE(Reads(*FindTagKey("dissipation"), constant, FrictionKind::kNone));
  EXPECT_FALSE(Reads(*FindTagKey("dissipation"), kelvin, FrictionKind::kNone));
  EXPECT_FALSE(Reads(*FindTagKey("exponent"), kelvin, FrictionKind::kNone));
  EXPECT_TRUE(Reads(*FindTagKey("damping"), kelvin, FrictionKind::kNone));
  EXPECT_TRUE(Reads(*FindTagKey("bristle_damping"), hertz, FrictionKind::kLuGre));
  EXPECT_FALSE(Reads(*FindTagKey("bristle_damping"), hertz, FrictionKind::kStribeck));
  EXPECT_TRUE(Reads(*FindTagKey("viscous"), hertz, FrictionKind::kStribeck));
  EXPECT_FALSE(Reads(*FindTagKey("tangential_ratio"), hertz, FrictionKind::kRegularized));
  EXPECT_FALSE(Reads(*FindTagKey("mu"), hertz, FrictionKind::kNone));
}

TEST(TagKeysTest, AKeyRefusedWhereUnreadIsRefusedOnALawThatDoesNotReadIt) {
  EXPECT_EQ(PairTagError("geom1=a geom2=b law=hertz stiffness=1e8 dissipation=0.5"),
            fmt::format("s.xml: contactlaw:t: dissipation=0.5 is not read by law=hertz, which "
                        "takes: {}",
                        Law(*ParseLawName("hertz")).parameters));
}

TEST(TagKeysTest, TheDefaultsAreTheParameters) {
  EXPECT_EQ(FindTagKey("exponent")->fallback, LawParams().exponent);
  EXPECT_EQ(FindTagKey("min_impact_velocity")->fallback, kDefaultMinImpactVelocity);
  EXPECT_EQ(FindTagKey("stribeck_velocity")->fallback, kDefaultStribeckVelocity);
  EXPECT_EQ(FindTagKey("restitution")->fallback, std::nullopt);
}

TEST(TagKeysTest, TheTagsPageListsEveryKey) {
  // the rows of its table of keys
  std::ifstream file(CONTACTLAWS_SOURCE_DIR "/docs/tags.md");
  std::string rows, line;
  while (std::getline(file, line)) {
    if (line.rfind("| `", 0) == 0) rows += line + "\n";
  }
  ASSERT_FALSE(rows.empty());
  for (const TagKey& key : TagKeys()) {
    const std::regex word(fmt::format("[` ,]{}[` ,]", key.name));
    EXPECT_TRUE(std::regex_search(rows, word)) << key.name;
  }
}

}  // namespace
}  // namespace contactlaws
