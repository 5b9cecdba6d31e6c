// Copyright contactlaws authors.
//
// render's look for a scene without visuals of its own
// (render/scene_look.h): a plain die on a plane is no longer one grey, its
// sky, floor and die distinct; a scene's own visuals are kept, element by
// element, and a scene that has them all draws the same bytes as with
// --plain (MuJoCo's defaults); the dressed model steps bit for bit as the
// scene's.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "cli_test_util.h"
#include "contactlaws/contact_model.h"
#include "png_image.h"
#include "render/scene_look.h"

namespace contactlaws {
namespace {

using testing::Image;
using testing::ReadPng;
using testing::Result;
using testing::RunCli;

constexpr int kWidth = 320;
constexpr int kHeight = 240;

// A 2 cm die resting on a plane, nothing else: no light, material, colour
// or sky, as most hand-written scenes. The side camera looks at it from
// 0.5 m, pitched down 4.6 degrees: the horizon at 40% of the height, the
// die in the middle (about 11 pixels across).
constexpr char kPlainDie[] = R"(<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 0.1" {floor}/>
    <camera name="side" pos="0 -0.5 0.05" xyaxes="1 0 0 0 0.04 0.5"/>
    {world}
    <body name="die" pos="0 0 0.01">
      <freejoint/>
      <geom name="die" type="box" size="0.01 0.01 0.01" mass="0.008" {die}/>
    </body>
  </worldbody>
  <custom><text name="contactlaw:die-floor"
    data="geom1=die geom2=floor law=hunt-crossley restitution=0.6 stiffness=2e8"/></custom>
</mujoco>)";

// The same die and plane with every visual of their own.
constexpr char kOwnLook[] = R"(<asset>
  <texture name="sky" type="skybox" builtin="gradient" rgb1="0.8 0.6 0.4" rgb2="0 0 0"
           width="32" height="32"/>
  <texture name="grid" type="2d" builtin="checker" rgb1="0.9 0.9 0.9" rgb2="0.5 0.5 0.5"
           width="32" height="32"/>
  <material name="ground" texture="grid" texrepeat="4 4" texuniform="true"/>
</asset>)";

// The die scene with what is given: elements in the world, attributes of
// the die and the floor, and sections before the world.
std::string PlainDie(const std::string& name, const std::string& world = "",
                     const std::string& die = "", const std::string& before = "",
                     const std::string& floor = "") {
  std::string xml = fmt::format(kPlainDie, fmt::arg("floor", floor), fmt::arg("world", world),
                                fmt::arg("die", die));
  xml.insert(xml.find("<worldbody>"), before);
  return testing::WriteScene(name, xml);
}

// The first frame of render SCENE (--camera side) with the extra options.
Image FirstFrame(const std::string& scene, const std::string& options, const std::string& dir) {
  const Result r = RunCli(fmt::format("render {} --camera side --duration 0.01 --fps 10 --width {} "
                                      "--height {} --output {}/ {}",
                                      scene, kWidth, kHeight, dir, options));
  EXPECT_EQ(r.status, 0) << r.output;
  return ReadPng(dir + "/frame_00000.png");
}

// The share of the frame's pixels that have its most common colour.
double MostCommonShare(const Image& image) {
  std::map<std::tuple<int, int, int>, long> counts;
  long most = 0;
  for (size_t i = 0; i < image.rgb.size(); i += 3) {
    most = std::max(most, ++counts[{image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]}]);
  }
  return static_cast<double>(most) / (image.width * image.height);
}

struct Colour {
  double rgb[3] = {0, 0, 0};
  double DistanceTo(const Colour& c) const {
    return std::hypot(rgb[0] - c.rgb[0], rgb[1] - c.rgb[1], rgb[2] - c.rgb[2]);
  }
};

// The mean colour of the pixels in [x0, x1) x [y0, y1), shares of the frame.
Colour MeanColour(const Image& image, double x0, double x1, double y0, double y1) {
  Colour mean;
  long n = 0;
  for (int y = static_cast<int>(y0 * image.height); y < y1 * image.height; ++y) {
    for (int x = static_cast<int>(x0 * image.width); x < x1 * image.width; ++x) {
      for (int c = 0; c < 3; ++c) mean.rgb[c] += image.at(x, y)[c];
      ++n;
    }
  }
  for (double& c : mean.rgb) c /= std::max(n, 1L);
  return mean;
}

// The sky (between the overlay, top, and the horizon at 40%), the floor
// (the bottom rows) and the die (the middle, within its 11 pixels).
Colour Sky(const Image& image) { return MeanColour(image, 0.05, 0.95, 0.25, 0.35); }
Colour Floor(const Image& image) { return MeanColour(image, 0.05, 0.95, 0.9, 0.98); }
Colour Die(const Image& image) { return MeanColour(image, 0.49, 0.51, 0.49, 0.51); }

// MuJoCo's defaults draw the plain die as one grey: 82% of the tracking
// camera's 320x240 frame is one colour (89% at 480x360). The samples' look:
// at most half (the checker's dark squares); in the side view the die at
// least kDieDistinct from the sky and the floor (RGB distance, of 441: a
// red from an orange is 60), the sky's gradient and the floor at least
// kSkyDistinct apart (both blue-grey in MuJoCo's samples; the tracking
// camera's frame under MuJoCo's defaults has them the same grey).
constexpr double kPlainShare = 0.8;
constexpr double kLookShare = 0.5;
constexpr double kDieDistinct = 60;
constexpr double kSkyDistinct = 20;

TEST(RenderLookTest, PlainDieIsNoLongerOneGrey) {
  const std::string scene = PlainDie("look_plain_die");
  const std::string dir = ::testing::TempDir() + "/look_plain_die";
  for (const bool plain : {true, false}) {
    const std::string options = plain ? "--plain" : "";
    const Result r = RunCli(fmt::format("render {} --duration 0.01 --fps 10 --width {} --height {} "
                                        "--output {}_track/ {}",
                                        scene, kWidth, kHeight, dir, options));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("MuJoCo's samples' look") == std::string::npos, plain) << r.output;
    const double share = MostCommonShare(ReadPng(dir + "_track/frame_00000.png"));
    const Image side = FirstFrame(scene, options, dir + "_side");
    const double sky_floor = Sky(side).DistanceTo(Floor(side));
    const double die_floor = Die(side).DistanceTo(Floor(side));
    const double die_sky = Die(side).DistanceTo(Sky(side));
    RecordProperty(plain ? "plain" : "look",
                   fmt::format("share {:.3f}, sky-floor {:.1f}, die-floor {:.1f}, die-sky {:.1f}",
                               share, sky_floor, die_floor, die_sky));
    if (plain) {
      EXPECT_GT(share, kPlainShare);
      continue;
    }
    EXPECT_LT(share, kLookShare);
    EXPECT_GT(sky_floor, kSkyDistinct);
    EXPECT_GT(die_floor, kDieDistinct);
    EXPECT_GT(die_sky, kDieDistinct);
  }
}

TEST(RenderLookTest, SceneWithItsOwnLookDrawsTheSameBytes) {
  const std::string own = PlainDie("look_own", R"(<light pos="0 0 1" dir="0 0 -1"/>)",
                                   R"(rgba="0.2 0.6 0.2 1")", kOwnLook, R"(material="ground")");
  const Image plain = FirstFrame(own, "--plain", ::testing::TempDir() + "/look_own_plain");
  const Image look = FirstFrame(own, "", ::testing::TempDir() + "/look_own_look");
  ASSERT_FALSE(plain.rgb.empty());
  EXPECT_TRUE(plain.rgb == look.rgb);
}

// Element by element: what a scene has of its own is not added.
TEST(RenderLookTest, EachElementOfItsOwnIsKept) {
  const auto plan_of = [](const std::string& world, const std::string& die,
                          const std::string& before, const std::string& floor = "") {
    const UniqueModel m = LoadModelFile(PlainDie("look_element", world, die, before, floor));
    return render::PlanLook(m.get());
  };
  const render::LookPlan bare = plan_of("", "", "");
  EXPECT_TRUE(bare.sky && bare.light);
  EXPECT_EQ(bare.floors, std::vector<int>{0});
  EXPECT_EQ(bare.painted, std::vector<int>{1});
  EXPECT_DOUBLE_EQ(bare.square, 0.1);  // 5 of the die's 3.46 cm diagonals: 17 cm, down to 1-2-5

  const render::LookPlan lit = plan_of(R"(<light dir="0 0 -1"/>)", R"(rgba="1 0 0 1")", "");
  EXPECT_FALSE(lit.light);
  EXPECT_TRUE(lit.painted.empty());
  EXPECT_TRUE(lit.sky);

  const render::LookPlan own = plan_of("", R"(material="ground")", kOwnLook);
  EXPECT_FALSE(own.sky);
  EXPECT_TRUE(own.painted.empty());
  EXPECT_EQ(own.floors, std::vector<int>{0});  // the plane has none of its own

  EXPECT_TRUE(plan_of("", "", "", R"(rgba="0.3 0.3 0.3 1")").floors.empty());
  EXPECT_TRUE(plan_of("", "", kOwnLook, R"(material="ground")").floors.empty());
}

// One long geom does not set the squares: a 1 m plank on a hinge with a
// ball (6 cm) and a block (4 cm) on it: 5 of the median diameter (the
// block's 6.9 cm diagonal), 35 cm, down to 0.2 m; by the plank's 1 m they
// would be 5 m, larger than the 4 m floor.
TEST(RenderLookTest, TheSquaresFollowTheTypicalBodyNotTheLongest) {
  const UniqueModel m = LoadModelString(R"(<mujoco><worldbody>
    <geom type="plane" size="2 2 0.1"/>
    <body pos="0 0 0.3"><joint type="hinge" axis="0 1 0"/>
      <geom type="box" size="0.5 0.05 0.01"/></body>
    <body pos="0.4 0 0.8"><freejoint/><geom type="sphere" size="0.03"/></body>
    <body pos="-0.4 0 0.33"><freejoint/><geom type="box" size="0.02 0.02 0.02"/></body>
  </worldbody></mujoco>)", "seesaw.xml");
  EXPECT_DOUBLE_EQ(render::PlanLook(m.get()).square, 0.2);
}

// Visual only: the dressed model steps bit for bit as the scene's (a die
// dropped and tumbling on the plane, MuJoCo's own contact).
TEST(RenderLookTest, DressedModelStepsAsTheScene) {
  const std::string scene = PlainDie("look_steps");
  const UniqueModel plain = LoadModelFile(scene);
  const render::LookPlan plan = render::PlanLook(plain.get());
  const UniqueModel dressed = render::Dressed(plain.get(), scene, plan);
  ASSERT_EQ(dressed->nlight, 1);
  ASSERT_EQ(dressed->ntex, 2);
  EXPECT_EQ(dressed->geom_matid[0], 0);
  const UniqueData a(mj_makeData(plain.get()));
  const UniqueData b(mj_makeData(dressed.get()));
  for (mjData* d : {a.get(), b.get()}) {
    d->qpos[2] = 0.05;
    d->qvel[0] = 0.3;
    d->qvel[4] = 20;
  }
  for (int step = 0; step < 2000; ++step) {
    mj_step(plain.get(), a.get());
    mj_step(dressed.get(), b.get());
  }
  EXPECT_GT(a->ncon, 0);
  EXPECT_TRUE(std::equal(a->qpos, a->qpos + plain->nq, b->qpos));
  EXPECT_TRUE(std::equal(a->qvel, a->qvel + plain->nv, b->qvel));
}

}  // namespace
}  // namespace contactlaws
