// Copyright contactlaws authors.
//
// The tags read once (scene/parsed_tags.h) and the values set on them
// (Overrides::values): a Scene reads its tags' text once, its simulations
// none; a value set as a number is the tag's own word to the bit.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

using SceneTest = testing::MujocoTest;

// Every field of a pair's law and friction, to the bit.
void ExpectSamePair(const GeomPair& a, const GeomPair& b, const std::string& what) {
  const LawParams& l = a.params;
  const LawParams& k = b.params;
  EXPECT_EQ(l.law, k.law) << what;
  for (const auto& [x, y] : {std::pair{l.restitution, k.restitution}, {l.stiffness, k.stiffness},
                             {l.exponent, k.exponent}, {l.linear_stiffness, k.linear_stiffness},
                             {l.min_impact_velocity, k.min_impact_velocity},
                             {l.hysteresis, k.hysteresis}}) {
    EXPECT_EQ(x, y) << what;
  }
  EXPECT_EQ(l.damping, k.damping) << what;
  EXPECT_EQ(l.dissipation, k.dissipation) << what;
  const FrictionParams& f = a.friction;
  const FrictionParams& g = b.friction;
  EXPECT_EQ(f.kind, g.kind) << what;
  EXPECT_EQ(f.stiffness_rule, g.stiffness_rule) << what;
  EXPECT_EQ(f.damping_rule, g.damping_rule) << what;
  EXPECT_EQ(f.bristle_damping, g.bristle_damping) << what;
  for (const auto& [x, y] :
       {std::pair{f.mu_static, g.mu_static}, {f.mu_kinetic, g.mu_kinetic},
        {f.transition_velocity, g.transition_velocity},
        {f.stribeck_velocity, g.stribeck_velocity},
        {f.tangential_stiffness, g.tangential_stiffness},
        {f.tangential_ratio, g.tangential_ratio}, {f.tangential_damping, g.tangential_damping},
        {f.tangential_damping_ratio, g.tangential_damping_ratio},
        {f.bristle_stiffness, g.bristle_stiffness}, {f.viscous, g.viscous},
        {f.torsional, g.torsional}, {f.rolling, g.rolling}}) {
    EXPECT_EQ(x, y) << what;
  }
}

// A fit's values (Overrides::values) set on every tag as numbers give each
// pair what the same keys written in the tags give, derived coefficients
// included (a(e), Hertz's K of the materials, Mindlin's ratio, mu_kinetic
// from mu), and are refused as the tag's own values, naming the key, the
// value, the file and the range.
TEST_F(SceneTest, ValuesSetOnTheTagsAreTheirOwnWords) {
  const std::string scene = R"(<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="ball" pos="0 0 0.2"><freejoint/><geom name="ball" type="sphere" size="0.1"/></body>
    <body name="rod" pos="1 0 0.2"><freejoint/><geom name="rod" type="capsule" size="0.05 0.2"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:round" data="geom1=ball geom2=floor law=flores restitution=0.8 {0}"/>
    <text name="contactlaw:long" data="geom1=rod geom2=floor law=hunt-crossley restitution=0.8 {0} friction=stribeck"/>
  </custom>
</mujoco>)";
  struct Case {
    std::string tag;  // the round tag's stiffness or materials
    std::vector<KeyValue> values;
  };
  const Case cases[] = {
      {"stiffness=1e5", {{"restitution", 0.1 + 0.2}, {"stiffness", 3.3e5}, {"exponent", 1.7}}},
      {"stiffness=1e5", {{"mu", 0.35}, {"stribeck_velocity", 1.0 / 3}, {"viscous", 0.2}}},
      {"stiffness=1e5", {{"mu_static", 0.5}, {"mu_kinetic", 0.4}, {"tangential_ratio", 0.6}}},
      {"youngs1=2e9 poisson1=0.3 youngs2=7e10 poisson2=0.33",
       {{"youngs1", 3.1e9}, {"poisson2", 0.25}, {"min_impact_velocity", 0.1}}},
      {"stiffness=1e5", {{"tangential_damping_ratio", 0.7}, {"restitution", 0.55}}},
  };
  for (const Case& c : cases) {
    Overrides written, set;
    for (const KeyValue& v : c.values) {
      written.keys.emplace_back(v.key, fmt::format("{:.17g}", v.value));
    }
    set.values = c.values;
    UniqueModel m = LoadModelString(fmt::format(scene, c.tag), "v.xml");
    const ContactModel by_words(m.get(), "v.xml", written);
    const ContactModel by_values(m.get(), "v.xml", set);
    ASSERT_EQ(by_words.pairs().size(), by_values.pairs().size());
    for (size_t i = 0; i < by_words.pairs().size(); ++i) {
      ExpectSamePair(by_words.pairs()[i], by_values.pairs()[i], c.values[0].key);
    }
    // the values moved the pair off the tag's own parameters
    const ContactModel as_written(m.get(), "v.xml");
    EXPECT_TRUE(as_written.pairs()[0].params.restitution != by_values.pairs()[0].params.restitution ||
                as_written.pairs()[0].params.stiffness != by_values.pairs()[0].params.stiffness ||
                as_written.pairs()[0].friction.mu_kinetic != by_values.pairs()[0].friction.mu_kinetic ||
                as_written.pairs()[0].friction.tangential_damping_ratio !=
                    by_values.pairs()[0].friction.tangential_damping_ratio)
        << c.values[0].key;
  }
  // refused as the tag's own value, naming the key, value, file and range
  UniqueModel m = LoadModelString(fmt::format(scene, "stiffness=1e5"), "v.xml");
  auto refusal = [&](const std::vector<KeyValue>& values) -> std::string {
    Overrides o;
    o.values = values;
    try {
      ContactModel cm(m.get(), "v.xml", o);
    } catch (const Error& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_EQ(refusal({{"restitution", 1.5}}),
            "v.xml: contactlaw:round: restitution=1.5 must be in [0, 1]");
  EXPECT_EQ(refusal({{"stiffness", -2e5}}),
            "v.xml: contactlaw:round: stiffness=-200000 must be > 0 (N/m^n)");
  EXPECT_EQ(refusal({{"law", 1}}), "v.xml: contactlaw:round: 'law' is not a numeric contactlaw "
                                   "tag key");
  EXPECT_EQ(refusal({{"mu_static", 0.2}, {"mu_kinetic", 0.3}}),
            "v.xml: contactlaw:round: mu_kinetic=0.3 must be in [0, mu_static=0.2]");
  EXPECT_EQ(refusal({{"dissipation", 0.1}}),
            "v.xml: contactlaw:round: dissipation=0.1 is not read by law=flores, which takes: " +
                std::string(Law(*ParseLawName("flores")).parameters));
}

// A Scene reads its tags' text when it is made: its simulations, of its model
// or of an edited copy, read none (the text overwritten afterwards with words
// the parser refuses changes nothing), and a tag the parser refused is
// refused where a simulation reads it, with the parser's message.
TEST_F(SceneTest, ASceneReadsItsTagsOnce) {
  const std::string scene = R"(<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="ball" pos="0 0 0.2"><freejoint/><geom name="ball" type="sphere" size="0.1"/></body>
    <body name="paddle" mocap="true" pos="1 0 0.1"><geom type="box" size="0.1 0.1 0.01"/></body>
  </worldbody>
  <custom>
    <text name="contactlaw:ball-floor" data="geom1=ball geom2=floor law=flores restitution=0.8 stiffness={}"/>
    <text name="contactdrive:paddle" data="body=paddle amplitude=0.01 omega=30"/>
  </custom>
</mujoco>)";
  const Scene once("once.xml", LoadModelString(fmt::format(scene, "1e5"), "once.xml"));
  SimulationOptions options;
  options.overrides.values = {{"restitution", 0.5}};
  auto bounce = [&](std::unique_ptr<Simulation> sim) {
    while (sim->time() < 0.3) sim->Step(1e-4);
    return std::pair{sim->data()->qpos[2], sim->data()->mocap_pos[2]};
  };
  auto copy = [&] { return UniqueModel(mj_copyModel(nullptr, once.model())); };
  const auto shared = bounce(once.Make(options));
  const auto copied = bounce(once.Make(options, copy()));
  EXPECT_EQ(shared, copied);
  mjModel* m = const_cast<mjModel*>(once.model());  // the test's own model
  for (int i = 0; i < m->ntextdata; ++i) {
    if (m->text_data[i] != '\0') m->text_data[i] = '!';
  }
  EXPECT_THROW(ContactModel(once.model(), "once.xml"), Error);
  EXPECT_EQ(bounce(once.Make(options)), shared);
  EXPECT_EQ(bounce(once.Make(options, copy())), shared);

  // a copy of another model is refused
  const Scene other("other.xml", LoadModelString(fmt::format(scene, "2e5"), "other.xml"));
  EXPECT_THROW(once.Make(options, UniqueModel(mj_copyModel(nullptr, other.model()))), Error);

  // a bad tag: the scene is made, its simulations refused
  const Scene bad("bad.xml", LoadModelString(fmt::format(scene, "abc"), "bad.xml"));
  try {
    bad.Make({});
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "bad.xml: contactlaw:ball-floor: stiffness=abc is not a finite number");
  }
}

}  // namespace
}  // namespace contactlaws
