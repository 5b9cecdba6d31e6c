// Copyright contactlaws authors.
//
// The tag grammar on its own (no model): keys, values and their ranges, with
// messages that name the file, the tag, the key and the value.

#include "scene/tags.h"

#include <string>

#include <gtest/gtest.h>

#include "contactlaws/contact_model.h"
#include "scene/pair_tag_error.h"

namespace contactlaws {
namespace {

using internal::PairTagSpec;
using internal::ParsePairTag;

TEST(TagsTest, APairTagIsReadWhole) {
  const PairTagSpec spec = ParsePairTag(
      "s.xml", "contactlaw:ball-floor",
      "geom1=ball geom2=group:2 law=flores restitution=0.9 stiffness=1.4e8 exponent=1.5 "
      "min_impact_velocity=0.01 allow_tension=true");
  EXPECT_EQ(spec.label, "ball-floor");
  EXPECT_EQ(spec.geom1, "ball");
  EXPECT_EQ(spec.geom2, "group:2");
  EXPECT_EQ(spec.law, *ParseLawName("flores"));
  EXPECT_EQ(spec.restitution, 0.9);
  EXPECT_EQ(spec.stiffness, 1.4e8);
  EXPECT_EQ(spec.exponent, 1.5);
  EXPECT_EQ(spec.min_impact_velocity, 0.01);
  EXPECT_EQ(spec.allow_tension, true);
}

TEST(TagsTest, WithKeysReplacesInPlaceAndAppendsTheRest) {
  EXPECT_EQ(WithKeys("geom1=a geom2=b law=flores  restitution=0.1\n mu=0.2",
                     {{"restitution", "0.5"}, {"stiffness", "1e6"}, {"restitution", "0.7"}}),
            "geom1=a geom2=b law=flores restitution=0.7 mu=0.2 stiffness=1e6");
  EXPECT_EQ(WithKeys("geom1=a", {}), "geom1=a");
  EXPECT_EQ(WithKeys("", {{"law", "hertz"}}), "law=hertz");
}

TEST(TagsTest, BadValuesAreNamed) {
  const std::string ok = "geom1=a geom2=b law=hertz ";
  EXPECT_EQ(PairTagError(ok + "stiffness=1e8"), "");
  EXPECT_EQ(PairTagError(ok + "stiffness=0x10"),
            "s.xml: contactlaw:t: stiffness=0x10 is not a finite number");
  EXPECT_EQ(PairTagError(ok + "stiffness=-1"),
            "s.xml: contactlaw:t: stiffness=-1 must be > 0 (N/m^n)");
  EXPECT_EQ(PairTagError(ok + "stiffness=1e8 restitusion=1"),
            "s.xml: contactlaw:t: unknown key 'restitusion' (did you mean 'restitution'?)");
  EXPECT_EQ(PairTagError(ok + "stiffness=1e8 stiffness=2e8"),
            "s.xml: contactlaw:t: key 'stiffness' is given twice");
  EXPECT_EQ(PairTagError("geom1=a geom2=b law=hooke stiffness=1"),
            "s.xml: contactlaw:t: law=hooke is not a law (" + LawNameList() + ")");
  EXPECT_EQ(PairTagError(ok + "stiffness"),
            "s.xml: contactlaw:t: 'stiffness' is not of the form key=value");
}

TEST(TagsTest, FrictionKeysAreReadAndBadOnesNamed) {
  const PairTagSpec spec = ParsePairTag(
      "s.xml", "contactlaw:t",
      "geom1=a geom2=b law=hertz stiffness=1 friction=stribeck mu_static=0.6 mu_kinetic=0.4 "
      "stribeck_velocity=0.02 tangential_stiffness=1e5 tangential_damping=3 viscous=0.1");
  EXPECT_EQ(spec.friction.kind, FrictionKind::kStribeck);
  EXPECT_EQ(spec.friction.mu_static, 0.6);
  EXPECT_EQ(spec.friction.mu_kinetic, 0.4);
  EXPECT_EQ(spec.friction.stribeck_velocity, 0.02);
  EXPECT_EQ(spec.friction.tangential_stiffness, 1e5);
  EXPECT_EQ(spec.friction.tangential_damping, 3);
  EXPECT_EQ(spec.friction.viscous, 0.1);
  const std::string ok = "geom1=a geom2=b law=hertz stiffness=1 ";
  EXPECT_EQ(PairTagError(ok + "friction=coulmb"),
            "s.xml: contactlaw:t: friction=coulmb is not a friction model (" +
                FrictionNameList() + "): did you mean 'coulomb'?");
  EXPECT_EQ(PairTagError(ok + "mu=-0.1"), "s.xml: contactlaw:t: mu=-0.1 must be >= 0");
  EXPECT_EQ(PairTagError(ok + "mu_static=0.3 mu_kinetic=0.5"),
            "s.xml: contactlaw:t: mu_kinetic=0.5 must be in [0, mu_static=0.3]");
  EXPECT_EQ(PairTagError(ok + "mu=0.3 mu_static=0.5"),
            "s.xml: contactlaw:t: mu=0.3 and mu_static exclude each other (mu sets both)");
  EXPECT_EQ(PairTagError(ok + "tangential_stiffness=0"),
            "s.xml: contactlaw:t: tangential_stiffness=0 must be > 0 (N/m)");
  // Mindlin's spring and its damping ratio (friction.h)
  const PairTagSpec mindlin = ParsePairTag(
      "s.xml", "contactlaw:t", ok + "tangential_ratio=0.9 tangential_damping_ratio=0.25");
  EXPECT_EQ(mindlin.friction.tangential_ratio, 0.9);
  EXPECT_EQ(mindlin.friction.tangential_damping_ratio, 0.25);
  EXPECT_EQ(PairTagError(ok + "tangential_ratio=0"),
            "s.xml: contactlaw:t: tangential_ratio=0 must be > 0 (k_t over dF_n/dd)");
  EXPECT_EQ(PairTagError(ok + "tangential_damping_ratio=1.5"),
            "s.xml: contactlaw:t: tangential_damping_ratio=1.5 must be in [0, 1] (1: critical)");
  EXPECT_EQ(PairTagError(ok + "tangential_damping_ratio=-0.1"),
            "s.xml: contactlaw:t: tangential_damping_ratio=-0.1 must be in [0, 1] (1: critical)");
  EXPECT_EQ(PairTagError(ok + "tangential_stiffness=1e5 tangential_ratio=0.8"),
            "s.xml: contactlaw:t: tangential_stiffness and tangential_ratio exclude each other");
  EXPECT_EQ(PairTagError(ok + "tangential_damping=1 tangential_damping_ratio=0.5"),
            "s.xml: contactlaw:t: tangential_damping and tangential_damping_ratio exclude each "
            "other");
  EXPECT_EQ(PairTagError(ok + "bristle_stiffness=-1"),
            "s.xml: contactlaw:t: bristle_stiffness=-1 must be > 0 (1/m, per newton of normal "
            "force)");
}

// torsional_friction and rolling_friction: lengths (MuJoCo's second and
// third friction coefficients), >= 0 and finite.
TEST(TagsTest, TorqueCapsAreLengthsAtLeastZero) {
  const std::string ok = "geom1=a geom2=b law=hertz stiffness=1 ";
  const PairTagSpec spec =
      ParsePairTag("s.xml", "contactlaw:t", ok + "torsional_friction=0.02 rolling_friction=0");
  EXPECT_EQ(spec.friction.torsional_friction, 0.02);
  EXPECT_EQ(spec.friction.rolling_friction, 0.0);
  EXPECT_EQ(spec.friction.first_key, "torsional_friction");
  EXPECT_EQ(PairTagError(ok + "torsional_friction=-0.01"),
            "s.xml: contactlaw:t: torsional_friction=-0.01 must be >= 0 (m, the torque cap over "
            "the normal force)");
  EXPECT_EQ(PairTagError(ok + "rolling_friction=inf"),
            "s.xml: contactlaw:t: rolling_friction=inf is not a finite number");
  EXPECT_EQ(PairTagError(ok + "rolling_fricton=0.1"),
            "s.xml: contactlaw:t: unknown key 'rolling_fricton' (did you mean "
            "'rolling_friction'?)");
}

TEST(TagsTest, ALinearDriveNeedsAFiniteSpeed) {
  const DriveTagSpec belt =
      ParseDriveTag("s.xml", "contactdrive:belt", "body=belt motion=linear axis=x speed=0.5");
  EXPECT_TRUE(belt.linear);
  EXPECT_EQ(belt.speed, 0.5);
  auto error = [](const std::string& data) {
    try {
      ParseDriveTag("s.xml", "contactdrive:belt", data);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("body=belt motion=linear axis=x"),
            "s.xml: contactdrive:belt: missing key speed (m/s, a finite number) for motion=linear");
  EXPECT_EQ(error("body=belt motion=linear axis=x speed=inf"),
            "s.xml: contactdrive:belt: speed=inf is not a finite number");
  EXPECT_EQ(error("body=belt motion=linear speed=1 amplitude=1"),
            "s.xml: contactdrive:belt: amplitude is not read by motion=linear, which takes: "
            "axis, speed (m/s)");
}

TEST(TagsTest, ADriveTagIsReadWhole) {
  const DriveTagSpec spec = ParseDriveTag("s.xml", "contactdrive:table",
                                          "body=table motion=sine axis=0,3,4 amplitude=0.1 "
                                          "omega=7.5 phase=1");
  EXPECT_EQ(spec.body, "table");
  EXPECT_DOUBLE_EQ(spec.axis[1], 0.6);
  EXPECT_DOUBLE_EQ(spec.axis[2], 0.8);
  EXPECT_EQ(spec.amplitude, 0.1);
  EXPECT_EQ(spec.omega, 7.5);
  EXPECT_EQ(spec.phase, 1.0);
}

TEST(TagsTest, NearestWordSuggestsOnlyWhatIsClose) {
  const std::string_view words[] = {"restitution", "stiffness", "exponent"};
  EXPECT_EQ(NearestWord("stifness", words, 3), "stiffness");
  EXPECT_EQ(NearestWord("exponant", words, 3), "exponent");
  EXPECT_EQ(NearestWord("colour", words, 3), "");
}

}  // namespace
}  // namespace contactlaws
