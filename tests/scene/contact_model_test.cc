// Copyright contactlaws authors.
//
// Tags resolved against a model: bad scenes are refused with one line naming
// the file, the tag, the key and the value; overrides apply before validation.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "sim/spelling.h"
#include "contactlaws/law.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class SceneTest : public testing::MujocoTest {
 protected:
  Simulation& LoadScene(const std::string& file, const SimulationOptions& options = {}) {
    return MakeSceneSimulation(file, options);
  }
};

// Bad scenes: each refused with the message that names the thing.
struct BadScene {
  const char* what;
  const char* custom;   // inside <custom>
  std::string message;  // expected message after "bad.xml: "
  const char* extra = "";  // more MJCF inside <mujoco>
};

const BadScene kBadScenes[] = {
    {"unknown law", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hooke stiffness=1"/>)",
     "contactlaw:p: law=hooke is not a law (" + LawNameList() + ")"},
    {"unknown key", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz stifness=1"/>)",
     "contactlaw:p: unknown key 'stifness' (did you mean 'stiffness'?)"},
    {"missing geom2", R"(<text name="contactlaw:p" data="geom1=ball law=hertz stiffness=1"/>)",
     "contactlaw:p: missing key geom2"},
    {"missing law", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor stiffness=1"/>)",
     "contactlaw:p: missing key law"},
    {"missing stiffness", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz"/>)",
     "contactlaw:p: missing key stiffness (or youngs1 poisson1 youngs2 poisson2) for law=hertz"},
    {"missing restitution", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=flores stiffness=1"/>)",
     "contactlaw:p: missing key restitution (law=flores needs it)"},
    {"geom not found", R"(<text name="contactlaw:p" data="geom1=bal geom2=floor law=hertz stiffness=1"/>)",
     "contactlaw:p: geom1=bal: no geom is named 'bal'"},
    {"empty group", R"(<text name="contactlaw:p" data="geom1=group:4 geom2=floor law=hertz stiffness=1"/>)",
     "contactlaw:p: geom1=group:4: no geom is in group 4"},
    {"restitution out of range", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=flores restitution=1.5 stiffness=1"/>)",
     "contactlaw:p: restitution=1.5 must be in [0, 1]"},
    {"not a number", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz stiffness=abc"/>)",
     "contactlaw:p: stiffness=abc is not a finite number"},
    {"nan", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz stiffness=nan"/>)",
     "contactlaw:p: stiffness=nan is not a finite number"},
    {"negative stiffness", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz stiffness=-3"/>)",
     "contactlaw:p: stiffness=-3 must be > 0 (N/m^n)"},
    {"flores e = 0", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=flores restitution=0 stiffness=1"/>)",
     "contactlaw:p: restitution=0 must be in (0, 1] for flores"},
    {"gonthier e = 0", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=gonthier restitution=0 stiffness=1"/>)",
     "contactlaw:p: restitution=0 must be in (0, 1] for gonthier"},
    {"exact e = 0", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=exact restitution=0 stiffness=1"/>)",
     "contactlaw:p: restitution=0 must be in (0, 1] for exact"},
    {"dissipation not read", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hunt-crossley restitution=0.5 dissipation=0.2 stiffness=1"/>)",
     "contactlaw:p: dissipation=0.2 is not read by law=hunt-crossley, which takes: stiffness K "
     "(N/m^n) > 0, exponent n in [1, 3], restitution e in [0, 1]"},
    {"dissipation missing", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hunt-crossley-constant stiffness=1"/>)",
     "contactlaw:p: missing key dissipation (law=hunt-crossley-constant takes: stiffness K "
     "(N/m^n) > 0, exponent n in [1, 3], dissipation c (s/m) >= 0)"},
    {"dissipation negative", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hunt-crossley-constant dissipation=-1 stiffness=1"/>)",
     "contactlaw:p: dissipation=-1 must be >= 0 (s/m)"},
    {"poisson", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz youngs1=1e9 poisson1=0.5 youngs2=1e9 poisson2=0.3"/>)",
     "contactlaw:p: poisson1=0.5 must be in (-1, 0.5)"},
    {"materials on a box", R"(<text name="contactlaw:p" data="geom1=crate geom2=floor law=hertz youngs1=2e11 poisson1=0.3 youngs2=2e11 poisson2=0.3"/>)",
     "contactlaw:p: (crate, floor): materials (youngs1 ...) give K through Hertz's formula from "
     "the radii of curvature at the contact, and the box crate has none (corners, edges and "
     "flat faces: spheres, capsules and planes have one): give stiffness (N/m^n) instead"},
    {"kelvin-voigt without k", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=kelvin-voigt restitution=0.5 stiffness=1e8 exponent=1.5"/>)",
     "contactlaw:p: law=kelvin-voigt needs linear_stiffness (N/m), or stiffness with exponent 1 or absent"},
    {"same geom twice", R"(<text name="contactlaw:p" data="geom1=ball geom2=ball law=hertz stiffness=1"/>)",
     "contactlaw:p: geom1 and geom2 are the same geom"},
    {"tagged twice", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz stiffness=1"/>
                        <text name="contactlaw:q" data="geom1=floor geom2=ball law=hertz stiffness=1"/>)",
     "contactlaw:q: (floor, ball) is already tagged by contactlaw:p"},
    {"plane-plane", R"(<text name="contactlaw:p" data="geom1=floor geom2=wall law=hertz stiffness=1"/>)",
     "contactlaw:p: (floor, wall): MuJoCo has no collision function for these geom types"},
    {"same body", R"(<text name="contactlaw:p" data="geom1=ball geom2=ball2 law=hertz stiffness=1"/>)",
     "contactlaw:p: (ball, ball2): the two geoms belong to the same body (or to bodies welded "
     "together)"},
    {"malformed word", R"(<text name="contactlaw:p" data="geom1=ball geom2 floor"/>)",
     "contactlaw:p: 'geom2' is not of the form key=value"},
    {"explicit pair", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz stiffness=1"/>)",
     "contactlaw:p: (ball, floor) is also a <contact><pair>, which bypasses the contact filter: "
     "remove one of the two",
     R"(<contact><pair geom1="ball" geom2="floor"/></contact>)"},
    {"passive disabled", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz stiffness=1"/>)",
     "<flag passive=\"disable\"/> turns off mjcb_passive, so the contact laws of 1 tag(s) would "
     "never act: remove the flag",
     R"(<option><flag passive="disable"/></option>)"},
    {"drive of a non-mocap body", R"(<text name="contactdrive:d" data="body=ball amplitude=1 omega=1"/>)",
     "contactdrive:d: body=ball: a driven body must be declared mocap=\"true\""},
};

TEST_F(SceneTest, BadScenesAreRefusedByName) {
  for (const BadScene& bad : kBadScenes) {
    const std::string xml = fmt::format(R"(
<mujoco>
  {}
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <geom name="wall" type="plane" size="1 1 0.1" zaxis="1 0 0"/>
    <body name="ball" pos="0 0 0.2"><freejoint/><geom name="ball" type="sphere" size="0.1"/>
      <geom name="ball2" type="sphere" size="0.05" pos="0 0 0.1"/></body>
    <body name="crate" pos="1 0 0.2"><freejoint/><geom name="crate" type="box" size="0.1 0.1 0.1"/></body>
  </worldbody>
  <custom>{}</custom>
</mujoco>)",
                                        bad.extra, bad.custom);
    UniqueModel m = LoadModelString(xml, "bad.xml");
    try {
      ContactModel cm(m.get(), "bad.xml");
      ADD_FAILURE() << bad.what << ": accepted";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), std::string("bad.xml: ") + bad.message) << bad.what;
    }
  }
}

TEST_F(SceneTest, FrictionComesFromTheGeomsAsMujocoCombinesThem) {
  UniqueModel m = LoadModelString(R"(<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1" friction="0.3 0.01 0.002" condim="4"/>
    <geom name="ice" type="plane" size="1 1 0.1" pos="0 0 -1" condim="1"/>
    <body name="ball" pos="0 0 0.2"><freejoint/>
      <geom name="ball" type="sphere" size="0.1" friction="0.7 0.005 0.004" condim="1"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz stiffness=1"/>
    <text name="contactlaw:q" data="geom1=ball geom2=ice law=hertz stiffness=1 mu=0.5"/>
  </custom>
</mujoco>)", "f.xml");
  const ContactModel cm(m.get(), "f.xml");
  // the larger of each coefficient, and of condim: 4 has torsion, no rolling
  const FrictionParams& p = cm.pairs()[0].friction;
  EXPECT_EQ(p.kind, FrictionKind::kCoulomb);
  EXPECT_EQ(p.mu_static, 0.7);
  EXPECT_EQ(p.mu_kinetic, 0.7);
  EXPECT_EQ(p.torsional, 0.01);
  EXPECT_EQ(p.rolling, 0);
  EXPECT_EQ(p.stiffness_rule, TangentialStiffnessRule::kNormalRatio);
  EXPECT_EQ(p.tangential_ratio, kMindlinRatio);
  // critical, resolved with the pair
  EXPECT_EQ(p.damping_rule, TangentialDampingRule::kRatio);
  EXPECT_EQ(p.tangential_damping_ratio, 1.0);
  // condim 1: frictionless, and the tag's friction key is warned about
  EXPECT_EQ(cm.pairs()[1].friction.kind, FrictionKind::kNone);
  ASSERT_EQ(cm.warnings().size(), 1u);
  EXPECT_EQ(cm.warnings()[0], "f.xml: contactlaw:q: (ball, ice): mu is not read: the pair is "
                              "frictionless (condim 1, as in MuJoCo)");
  // --friction and --mu override every pair that has friction
  Overrides overrides;
  overrides.friction = FrictionKind::kLuGre;
  overrides.mu = 0.2;
  const ContactModel over(m.get(), "f.xml", overrides);
  EXPECT_EQ(over.pairs()[0].friction.kind, FrictionKind::kLuGre);
  EXPECT_EQ(over.pairs()[0].friction.mu_kinetic, 0.2);
  EXPECT_EQ(over.pairs()[1].friction.kind, FrictionKind::kNone);
}

// A tag of materials gives its pair Mindlin's spring of their shear moduli
// and the normal law's damping ratio; a tag of stiffness keeps nu = 0.3 and
// the critical damper; the keys override either; a tangential key on a
// frictionless pair is warned about.
TEST_F(SceneTest, MaterialsGiveMindlinsSpringAndTheNormalDampingRatio) {
  UniqueModel m = LoadModelString(R"(<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <geom name="ice" type="plane" size="1 1 0.1" pos="0 0 -1" condim="1"/>
    <geom name="wall" type="plane" size="1 1 0.1" pos="0 0 -2"/>
    <geom name="slab" type="plane" size="1 1 0.1" pos="0 0 -3"/>
    <body name="ball" pos="0 0 0.2"><freejoint/><geom name="ball" type="sphere" size="0.1"/></body>
    <body name="puck" pos="1 0 0.2"><freejoint/>
      <geom name="puck" type="sphere" size="0.1" condim="1"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:p" data="geom1=ball geom2=floor law=exact restitution=0.9
      youngs1=380e9 poisson1=0.23 youngs2=70e9 poisson2=0.25"/>
    <text name="contactlaw:q" data="geom1=puck geom2=ice law=hertz stiffness=1
      tangential_damping_ratio=0.5"/>
    <text name="contactlaw:r" data="geom1=ball geom2=wall law=exact restitution=0.9
      youngs1=380e9 poisson1=0.23 youngs2=70e9 poisson2=0.25 tangential_ratio=0.7
      tangential_damping_ratio=1"/>
    <text name="contactlaw:s" data="geom1=ball geom2=slab law=exact restitution=0.9
      youngs1=380e9 poisson1=0.23 youngs2=70e9 poisson2=0.25 tangential_stiffness=5e5
      tangential_damping=3"/>
  </custom>
</mujoco>)", "mindlin.xml");
  const ContactModel cm(m.get(), "mindlin.xml");
  const FrictionParams& p = cm.pairs()[0].friction;
  EXPECT_EQ(p.stiffness_rule, TangentialStiffnessRule::kNormalRatio);
  EXPECT_EQ(p.tangential_ratio, MindlinRatio(380e9, 0.23, 70e9, 0.25));
  EXPECT_EQ(p.damping_rule, TangentialDampingRule::kNormalLaw);
  ASSERT_EQ(cm.warnings().size(), 1u);
  EXPECT_EQ(cm.warnings()[0], "mindlin.xml: contactlaw:q: (puck, ice): tangential_damping_ratio "
                              "is not read: the pair is frictionless (condim 1, as in MuJoCo)");
  const FrictionParams& r = cm.pairs()[2].friction;
  EXPECT_EQ(r.tangential_ratio, 0.7);
  EXPECT_EQ(r.damping_rule, TangentialDampingRule::kRatio);
  EXPECT_EQ(r.tangential_damping_ratio, 1.0);
  const FrictionParams& s = cm.pairs()[3].friction;
  EXPECT_EQ(s.stiffness_rule, TangentialStiffnessRule::kGiven);
  EXPECT_EQ(s.tangential_stiffness, 5e5);
  EXPECT_EQ(s.damping_rule, TangentialDampingRule::kGiven);
  EXPECT_EQ(s.tangential_damping, 3);
}

// The tag's torque caps replace the geoms' where condim has them, and are
// warned about where it does not.
TEST_F(SceneTest, TorqueCapKeysOverrideTheGeomsWhereCondimHasThem) {
  UniqueModel m = LoadModelString(R"(<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1" friction="0.3 0.01 0.002" condim="6"/>
    <geom name="floor4" type="plane" size="1 1 0.1" pos="0 0 -1" condim="4"/>
    <body name="ball" pos="0 0 0.2"><freejoint/>
      <geom name="ball" type="sphere" size="0.1" friction="0.7 0.005 0.004"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz stiffness=1
      torsional_friction=0.03 rolling_friction=0.001"/>
    <text name="contactlaw:q" data="geom1=ball geom2=floor4 law=hertz stiffness=1
      torsional_friction=0.02 rolling_friction=0.005"/>
  </custom>
</mujoco>)", "caps.xml");
  const ContactModel cm(m.get(), "caps.xml");
  EXPECT_EQ(cm.pairs()[0].friction.torsional, 0.03);
  EXPECT_EQ(cm.pairs()[0].friction.rolling, 0.001);
  // condim 4: torsion from the tag, no rolling, and the rolling key warned about
  EXPECT_EQ(cm.pairs()[1].friction.torsional, 0.02);
  EXPECT_EQ(cm.pairs()[1].friction.rolling, 0.0);
  ASSERT_EQ(cm.warnings().size(), 1u);
  EXPECT_EQ(cm.warnings()[0],
            "caps.xml: contactlaw:q: (ball, floor4): rolling_friction=0.005 is not read: the "
            "pair's condim is 4 (rolling resistance needs condim 6, as in MuJoCo)");
}

TEST_F(SceneTest, OverridesApplyBeforeValidation) {
  SimulationOptions options;
  options.overrides.law = *ParseLawName("kelvin-voigt");
  options.overrides.restitution = 0.4;
  Simulation& sim = LoadScene("bouncing_ball.xml", options);
  const LawParams& p = sim.contact_model().pairs().at(0).params;
  EXPECT_EQ(p.law, *ParseLawName("kelvin-voigt"));
  EXPECT_EQ(p.linear_stiffness, 5e6);
  EXPECT_EQ(p.restitution, 0.4);

  options.overrides = {};
  options.overrides.restitution = 0.0;  // flores refuses e = 0
  try {
    LoadScene("bouncing_ball.xml", options);
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "bouncing_ball.xml: contactlaw:ball-floor: restitution=0 must be in (0, 1] for "
                 "flores");
  }
}

// a(e) is resolved once per pair, where its parameters are made, from the
// restitution with the overrides applied: the bisection of `exact` runs
// there, not at each evaluation.
TEST_F(SceneTest, TheHysteresisCoefficientIsResolvedWithThePairsParameters) {
  SimulationOptions options;
  options.overrides.law = *ParseLawName("exact");
  options.overrides.restitution = 0.7;
  const LawParams& exact =
      LoadScene("bouncing_ball.xml", options).contact_model().pairs()[0].params;
  EXPECT_EQ(exact.hysteresis, ExactCoefficient(0.7));
  options.overrides = {};  // the tag's flores at e = 0.9: a = 8 (1 - e) / (5 e)
  const LawParams& flores =
      LoadScene("bouncing_ball.xml", options).contact_model().pairs()[0].params;
  EXPECT_EQ(flores.hysteresis, HysteresisCoefficient(*ParseLawName("flores"), 0.9));
  EXPECT_NEAR(flores.hysteresis, 8 * 0.1 / (5 * 0.9), 1e-15);
}

// The dissipation override is read by the laws that read it (the tag's is
// refused on the others), and a law that needs it without it is refused.
TEST_F(SceneTest, DissipationOverrideGoesToTheLawsThatReadIt) {
  SimulationOptions options;
  options.overrides.dissipation = 0.1;  // flores does not read it
  EXPECT_FALSE(LoadScene("bouncing_ball.xml", options)
                   .contact_model().pairs().at(0).params.dissipation.has_value());
  options.overrides.law = ParseLawName("hunt-crossley-constant");
  const LawParams& p = LoadScene("bouncing_ball.xml", options).contact_model().pairs().at(0).params;
  EXPECT_EQ(p.dissipation, 0.1);
  EXPECT_EQ(p.stiffness, 1.4e8);
  options.overrides.dissipation.reset();
  try {
    LoadScene("bouncing_ball.xml", options);
    ADD_FAILURE() << "accepted";
  } catch (const OptionError& e) {
    // the library names the override by its key (Overrides::dissipation), a
    // front-end by its own name for it
    const std::string missing =
        "bouncing_ball.xml: contactlaw:ball-floor: missing key dissipation "
        "(law=hunt-crossley-constant takes: stiffness K (N/m^n) > 0, exponent n in [1, 3], "
        "dissipation c (s/m) >= 0); the tag's law=flores does not read it: give the "
        "dissipation override ";
    EXPECT_EQ(e.what(), missing + "(dissipation)");
    EXPECT_EQ(Spelled(e, kCommandLineSpelling), missing + "(--dissipation)");
  }
}

}  // namespace
}  // namespace contactlaws
