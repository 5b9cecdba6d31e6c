// Copyright contactlaws authors.
//
// The scenes of mjcf/ run, and bad scenes are refused with one line naming
// the file, the tag, the key and the value.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "contactlaws/hysteresis.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

class SceneTest : public testing::MujocoTest {
 protected:
  Simulation& LoadScene(const std::string& file, const SimulationOptions& options = {}) {
    return MakeSceneSimulation(file, options);
  }
};

TEST_F(SceneTest, MujocoIsTwoTwoTwo) { EXPECT_EQ(MujocoVersion(), 222); }

TEST_F(SceneTest, BouncingBallIsThePapers) {
  Simulation& sim = LoadScene("bouncing_ball.xml");
  const mjModel* m = sim.model();
  const int ball = mj_name2id(m, mjOBJ_BODY, "ball");
  EXPECT_DOUBLE_EQ(m->body_mass[ball], 1.0);
  EXPECT_DOUBLE_EQ(m->body_inertia[3 * ball], 0.1);
  EXPECT_DOUBLE_EQ(m->geom_size[3 * mj_name2id(m, mjOBJ_GEOM, "ball")], 0.1);
  EXPECT_DOUBLE_EQ(sim.data()->qpos[2], 1.0);
  EXPECT_DOUBLE_EQ(m->opt.timestep, 1e-5);
  const GeomPair& pair = sim.contact_model().pairs().at(0);
  EXPECT_EQ(pair.params.kind, LawKind::kFlores);
  EXPECT_EQ(pair.params.restitution, 0.9);
  EXPECT_EQ(pair.params.stiffness, 1.4e8);
  EXPECT_EQ(pair.params.exponent, 1.5);

  // it falls 0.9 m and rebounds as the closed form says, up to gravity:
  // during a contact of duration tau, gravity shifts e_post by at most
  // g tau / v0 (~3e-3 here)
  const Impact impact = testing::FirstImpact(sim, 1.0);
  // the first state in contact is up to one step past the touch: g h = 1e-4
  EXPECT_NEAR(impact.impact_velocity, std::sqrt(2 * 9.81 * 0.9), 2e-4);
  const double tau = impact.time_separation - impact.time_contact;
  // the Hertz duration 2.94 delta_max / v0 = 1.33 ms, lengthened by damping
  EXPECT_NEAR(tau, 1.3e-3, 0.2e-3);
  EXPECT_NEAR(impact.restitution_post(),
              ExactRebound(HysteresisCoefficient(LawKind::kFlores, 0.9)),
              9.81 * tau / impact.impact_velocity);
}

TEST_F(SceneTest, BallTableRunsWithItsDrive) {
  for (const char* integrator : {"euler", "rk4"}) {
    SimulationOptions options;
    options.integrator = std::string(integrator) == "rk4" ? mjINT_RK4 : mjINT_EULER;
    options.timestep = 2e-5;
    Simulation& sim = LoadScene("ball_table.xml", options);
    ASSERT_EQ(sim.contact_model().drives().size(), 1u);
    std::vector<double> row;
    const std::vector<std::string> columns = sim.Columns();
    const auto column = [&](const char* name) {
      return std::find(columns.begin(), columns.end(), name) - columns.begin();
    };
    while (sim.time() < 1.5) {
      sim.Step();
      if (std::fmod(sim.time(), 0.1) < 2e-5) {
        sim.Sample(&row);
        // the hook places the table from d->time alone: exact but for the
        // rounding of sin and of the accumulated time (~1e-15)
        EXPECT_NEAR(row[column("table.z")], 0.5 + 0.1 * std::sin(7.5 * sim.time()), 1e-12);
        EXPECT_GT(row[column("ball.z")] - row[column("table.z")], 0.09) << "the ball stays above";
      }
    }
    EXPECT_GE(sim.contacts().impacts().size(), 2u) << integrator;
  }
}

// Bad scenes: each refused with the message that names the thing.
struct BadScene {
  const char* what;
  const char* custom;   // inside <custom>
  const char* message;  // expected message after "bad.xml: "
  const char* extra = "";  // more MJCF inside <mujoco>
};

const BadScene kBadScenes[] = {
    {"unknown law", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hooke stiffness=1"/>)",
     "contactlaw:p: law=hooke is not a law (hertz, kelvin-voigt, hunt-crossley, "
     "lankarani-nikravesh, flores)"},
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
    {"poisson", R"(<text name="contactlaw:p" data="geom1=ball geom2=floor law=hertz youngs1=1e9 poisson1=0.5 youngs2=1e9 poisson2=0.3"/>)",
     "contactlaw:p: poisson1=0.5 must be in (-1, 0.5)"},
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

TEST_F(SceneTest, MalformedXmlNamesTheFileAndLine) {
  try {
    LoadModelString("<mujoco>\n<worldbody>\n<geom type=\"sphere\" size=\"0.1\">\n</mujoco>", "broken.xml");
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("broken.xml: ", 0), 0u) << message;
    EXPECT_NE(message.find("Line number=3"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
  }
}

TEST_F(SceneTest, OverridesApplyBeforeValidation) {
  SimulationOptions options;
  options.overrides.law = LawKind::kKelvinVoigt;
  options.overrides.restitution = 0.4;
  Simulation& sim = LoadScene("bouncing_ball.xml", options);
  const LawParams& p = sim.contact_model().pairs().at(0).params;
  EXPECT_EQ(p.kind, LawKind::kKelvinVoigt);
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

}  // namespace
}  // namespace contactlaws
