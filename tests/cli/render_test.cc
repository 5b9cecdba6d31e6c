// Copyright contactlaws authors.
//
// contactlaws render: a video of the right frame count and size, frames that
// change where the ball moves, and in each frame the pose of the simulated
// state at its time (a falling ball's pixel row against its free-fall
// height projected through the scene's camera); the tracking camera
// framing a sliding die in every frame; a resting body's arrow as long as
// the body; the slow motion in the overlay; every scene of mjcf/ drawn; the
// bad inputs.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "cli_test_util.h"
#include "png_image.h"

namespace contactlaws {
namespace {

using testing::Image;
using testing::ReadPng;
using testing::Result;
using testing::RunCli;

constexpr int kWidth = 160;
constexpr int kHeight = 240;
constexpr double kGravity = 9.81;      // m/s^2
constexpr double kStartHeight = 1.0;   // m, the ball's centre at t = 0
constexpr double kCameraHeight = 0.6;  // m
constexpr double kCameraDistance = 3.0;  // m, along y to the ball
constexpr double kFovy = 45.0;         // degrees, MuJoCo's default
// The centroid of the ball's pixels against its projected centre: within a
// pixel (antialiased edge, a sphere's image centroid off its centre's
// projection by (r/D)^2 of its radius, here 1e-3 px). One frame period of
// error would be 10 to 30 pixels here.
constexpr double kPixelTolerance = 1.0;

// A body over a floor before a side camera (looking along +y) at distance
// and height; tagged (tag: the rest of the tag's data), so that the laws
// are on.
std::string SideScene(const std::string& name, double distance, double height,
                      const std::string& body, const std::string& tag) {
  return testing::WriteScene(name, fmt::format(R"(<mujoco>
  <option timestep="1e-4" gravity="0 0 -{g}" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <camera name="side" pos="0 -{d} {ch}" xyaxes="1 0 0 0 0 1" fovy="{fovy}"/>
    {body}
  </worldbody>
  <custom><text name="contactlaw:body-floor" data="geom1=body geom2=floor {tag}"/></custom>
</mujoco>)", fmt::arg("g", kGravity), fmt::arg("d", distance), fmt::arg("ch", height),
      fmt::arg("fovy", kFovy), fmt::arg("body", body), fmt::arg("tag", tag)));
}

// A red ball falling before the side camera.
std::string FallScene() {
  return SideScene("render_fall", kCameraDistance, kCameraHeight, fmt::format(R"(
    <body name="ball" pos="0 0 {}">
      <freejoint/>
      <geom name="body" type="sphere" size="0.1" mass="1" rgba="1 0 0 1"/>
    </body>)", kStartHeight), "law=hunt-crossley restitution=0.8 stiffness=1e7");
}

bool IsBall(const unsigned char* p) { return p[0] > 2 * p[1] + 20 && p[0] > 2 * p[2] + 20; }

// The mean row of the ball's pixels, top row 0; NaN when none.
double BallRow(const Image& image) {
  double sum = 0;
  long count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (IsBall(image.at(x, y))) {
        sum += y + 0.5;
        ++count;
      }
    }
  }
  return count ? sum / count : std::nan("");
}

// The row of a point at height z in the vertical plane of the camera at
// distance and height.
double ProjectedRow(double z, double distance = kCameraDistance, double height = kCameraHeight) {
  const double half_view = distance * std::tan(0.5 * kFovy * M_PI / 180);
  return 0.5 * kHeight * (1 - (z - height) / half_view);
}

std::string Frame(const std::string& dir, int k) {
  return fmt::format("{}/frame_{:05d}.png", dir, k);
}

TEST(RenderTest, EachFrameShowsTheStateAtItsTime) {
  const std::string dir = ::testing::TempDir() + "/render_frames";
  const Result r = RunCli(fmt::format("render {} --camera side --duration 0.4 --fps 10 "
                                      "--width {} --height {} --output {}/",
                                      FallScene(), kWidth, kHeight, dir));
  ASSERT_EQ(r.status, 0) << r.output;
  // frames at t = 0, 0.1, ..., 0.4: free fall, before the touch at 0.43 s
  for (int k = 0; k <= 4; ++k) {
    const double t = 0.1 * k;
    const double z = kStartHeight - 0.5 * kGravity * t * t;
    EXPECT_NEAR(BallRow(ReadPng(Frame(dir, k))), ProjectedRow(z), kPixelTolerance) << "t=" << t;
  }
  EXPECT_FALSE(std::ifstream(Frame(dir, 5)).good());  // no frame beyond the duration
}

TEST(RenderTest, FramesChangeWhereTheBallMoves) {
  const std::string dir = ::testing::TempDir() + "/render_change";
  const Result r = RunCli(fmt::format("render {} --camera side --duration 0.2 --fps 10 "
                                      "--width {} --height {} --output {}/",
                                      FallScene(), kWidth, kHeight, dir));
  ASSERT_EQ(r.status, 0) << r.output;
  const Image a = ReadPng(Frame(dir, 0));
  const Image b = ReadPng(Frame(dir, 2));
  // the ball's columns (radius 0.1 m at 3 m), with a pixel for the edge
  const double half_view = kCameraDistance * std::tan(0.5 * kFovy * M_PI / 180);
  const double radius_px = 0.1 / half_view * 0.5 * kHeight + 1;
  long in_ball_columns = 0;
  long elsewhere = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      if (std::equal(a.at(x, y), a.at(x, y) + 3, b.at(x, y))) continue;
      const bool overlay = y < kHeight / 5;  // the time and the tags, top left
      if (std::abs(x + 0.5 - 0.5 * kWidth) <= radius_px) {
        ++in_ball_columns;
      } else if (!overlay) {
        ++elsewhere;
      }
    }
  }
  EXPECT_GT(in_ball_columns, 100);
  EXPECT_EQ(elsewhere, 0);
}

// The frames' names in dir, in order.
std::vector<Image> ReadFrames(const std::string& dir, int count) {
  std::vector<Image> frames;
  for (int k = 0; k < count; ++k) frames.push_back(ReadPng(Frame(dir, k)));
  return frames;
}

// The box of the ball-coloured pixels: count and extent.
struct Blob {
  long count = 0;
  int left = 1 << 30, right = -1, top = 1 << 30, bottom = -1;
};

template <typename Is>
Blob FindBlob(const Image& image, Is is) {
  Blob blob;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!is(image.at(x, y))) continue;
      ++blob.count;
      blob.left = std::min(blob.left, x);
      blob.right = std::max(blob.right, x);
      blob.top = std::min(blob.top, y);
      blob.bottom = std::max(blob.bottom, y);
    }
  }
  return blob;
}

// A red 2 cm die dropped 4 cm onto a frictionless floor, sliding away at
// 1 m/s: 1 m in 1 s, 50 times its size.
std::string SlideScene() {
  return testing::WriteScene("render_slide", R"(<mujoco>
  <option timestep="1e-4" gravity="0 0 -9.81" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="die" pos="0 0 0.05">
      <freejoint/>
      <geom name="die" type="box" size="0.01 0.01 0.01" mass="0.008" rgba="1 0 0 1"/>
    </body>
  </worldbody>
  <keyframe><key qpos="0 0 0.05 1 0 0 0" qvel="1 0 0 0 0 0"/></keyframe>
  <custom><text name="contactlaw:die-floor"
    data="geom1=die geom2=floor law=hunt-crossley restitution=0.5 stiffness=1e7 friction=none"/>
  </custom>
</mujoco>)");
}

// The default camera follows the die across the floor and frames it: in
// every frame the die is whole (clear of the borders) and large, where
// MuJoCo's free camera of the model (framing the 10 m floor) shows it as a
// few pixels.
TEST(RenderTest, TrackingCameraFollowsAndFramesTheMovingBody) {
  constexpr int kFrames = 6;  // 0, 0.2, ..., 1 s
  // The die's share of the frame: its bounding box is a third of the view
  // box (kSurroundings), the die 0.58 of that box's side (a cube in its
  // bounding sphere's box); the view box's corners, margins and the
  // overlay's rows take the rest. Measured 1.7% to 2.3% of 160 x 120
  // (16 x 20 pixels and more).
  constexpr double kTrackedShare = 0.01;
  // The free camera's die: measured 7 pixels at most (0.04%), and none at
  // 1 s, where it has left the view.
  constexpr double kFreeShare = 0.001;
  const std::string scene = SlideScene();
  for (const char* camera : {"track", "free"}) {
    const std::string dir = ::testing::TempDir() + "/render_" + camera;
    const Result r = RunCli(fmt::format("render {} --camera {} --duration 1 --fps 5 --width 160 "
                                        "--height 120 --output {}/", scene, camera, dir));
    ASSERT_EQ(r.status, 0) << r.output;
    int k = 0;
    for (const Image& frame : ReadFrames(dir, kFrames)) {
      const Blob die = FindBlob(frame, IsBall);
      const double share = static_cast<double>(die.count) / (frame.width * frame.height);
      if (std::string(camera) == "free") {
        EXPECT_LT(share, kFreeShare) << "frame " << k;
      } else {
        EXPECT_GT(share, kTrackedShare) << "frame " << k;
        EXPECT_GT(die.left, 0) << "frame " << k;
        EXPECT_LT(die.right, frame.width - 1) << "frame " << k;
        EXPECT_GT(die.top, 0) << "frame " << k;
        EXPECT_LT(die.bottom, frame.height - 1) << "frame " << k;
      }
      ++k;
    }
  }
}

// contact_marks.cc's magenta at any brightness (the headlight alone lights
// the thin arrow: (110, 19, 64)), down to its antialiased tip
bool IsNormalArrow(const unsigned char* p) { return p[0] >= p[1] + 8 && p[2] >= p[1] + 4; }

// A resting body's normal-force arrow is as long as the body's size (its
// bounding sphere's diameter, 0.1732 m for a 10 cm cube): a cube resting on
// its four corners, seen from the side, gets one arrow from the middle of
// its bottom face whose tip stands 0.1732 m above the floor.
TEST(RenderTest, RestingBodysArrowIsItsSize) {
  constexpr double kSize = 0.1 * 1.7320508;  // m
  constexpr double kNear = 0.8;  // m, the camera's distance: the arrow 2 pixels wide
  constexpr double kLow = 0.15;  // m, the camera's height: the cube and the arrow in view
  // The head's last pixels are under half a pixel wide and fade into the
  // background: the tip seen is 4.4 pixels short of it (of 63 for the
  // arrow; the head's base, at 2/3 of it, is where it should be). An arrow
  // at half the length would end 31 pixels lower, inside the cube.
  constexpr double kTipTolerance = 6.0;  // pixels
  // at its static depth: each corner carries m g / 4 = K d^1.5
  const double depth = std::pow(1.0 * kGravity / 4 / 1e7, 2.0 / 3);
  const std::string scene = SideScene("render_rest", kNear, kLow, fmt::format(R"(
    <body name="cube" pos="0 0 {}">
      <freejoint/>
      <geom name="body" type="box" size="0.05 0.05 0.05" mass="1" rgba="0.2 0.2 0.8 1"/>
    </body>)", 0.05 - depth), "law=hunt-crossley restitution=0.5 stiffness=1e7 "
                              "min_impact_velocity=0.01 friction=none");
  const std::string dir = ::testing::TempDir() + "/render_rest";
  const Result r = RunCli(fmt::format("render {} --camera side --duration 0.2 --fps 5 --width {} "
                                      "--height {} --output {}/", scene, kWidth, kHeight, dir));
  ASSERT_EQ(r.status, 0) << r.output;
  const Blob arrow = FindBlob(ReadPng(Frame(dir, 1)), IsNormalArrow);
  ASSERT_GT(arrow.count, 0);
  EXPECT_NEAR(arrow.top, ProjectedRow(kSize - depth / 2, kNear, kLow), kTipTolerance);
}

// --slowmo is shown: the first frame at 2x differs from the one at 1x in the
// overlay only (the time, the tags and the slow motion, top left).
TEST(RenderTest, OverlayShowsTheSlowMotion) {
  std::vector<Image> first;
  for (const char* slowmo : {"1", "2"}) {
    const std::string dir = ::testing::TempDir() + "/render_slowmo" + slowmo;
    const Result r = RunCli(fmt::format("render {} --camera side --duration 0.01 --fps 10 "
                                        "--slowmo {} --width {} --height {} --output {}/",
                                        FallScene(), slowmo, kWidth, kHeight, dir));
    ASSERT_EQ(r.status, 0) << r.output;
    first.push_back(ReadPng(Frame(dir, 0)));
  }
  const Blob changed = FindBlob(first[0], [&](const unsigned char* p) {
    const size_t i = p - first[0].rgb.data();
    return !std::equal(p, p + 3, first[1].rgb.data() + i);
  });
  EXPECT_GT(changed.count, 0);
  // the overlay's three lines, 24 pixels each at MuJoCo's font at 100%:
  // measured to row 74
  EXPECT_LT(changed.bottom, kHeight * 3 / 8);
}

// The timestep a scene's <option> gives (0: the scene does not load).
double SceneTimestep(const std::string& path) {
  std::unique_ptr<mjModel, void (*)(mjModel*)> m(mj_loadXML(path.c_str(), nullptr, nullptr, 0),
                                                 mj_deleteModel);
  return m ? m->opt.timestep : 0;
}

// Every scene of mjcf/ (textures, skybox, shadows) draws two small frames,
// from at most 500 of its own steps (Chung & Ooi's, at 1e-8 s, would take 5
// million for 0.05 s): 1.5 frames of video at 20 fps, two whatever the rounding.
TEST(RenderTest, ShippedScenesDraw) {
  constexpr double kVideoSeconds = 0.075;
  constexpr double kMostSteps = 500;
  int scenes = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(CONTACTLAWS_SOURCE_DIR) + "/mjcf")) {
    if (entry.path().extension() != ".xml") continue;
    const double timestep = SceneTimestep(entry.path().string());
    ASSERT_GT(timestep, 0) << entry.path();
    const double duration = std::min(kVideoSeconds, kMostSteps * timestep);
    const std::string dir = ::testing::TempDir() + "/render_" + entry.path().stem().string();
    const Result r = RunCli(fmt::format("render {} --duration {} --fps 20 --slowmo {} --width 64 "
                                        "--height 48 --output {}/", entry.path().string(),
                                        duration, kVideoSeconds / duration, dir));
    EXPECT_EQ(r.status, 0) << entry.path() << r.output;
    EXPECT_EQ(ReadPng(Frame(dir, 1)).width, 64) << entry.path();
    ++scenes;
  }
  EXPECT_GE(scenes, 9);
}

// ffprobe's frame count and size of a video.
std::string Probe(const std::string& path) {
  std::FILE* pipe = popen(fmt::format("ffprobe -v error -count_frames -select_streams v:0 "
                                      "-show_entries stream=nb_read_frames,width,height "
                                      "-of csv=p=0 {}", path).c_str(), "r");
  char line[256] = "";
  if (!std::fgets(line, sizeof(line), pipe)) line[0] = 0;
  pclose(pipe);
  return line;
}

TEST(RenderTest, VideoHasTheFrameCountAndSize) {
  for (const char* extension : {"mp4", "gif"}) {
    const std::string path = ::testing::TempDir() + "/render_video." + extension;
    // 0.5 s at 20 fps x 2 slow motion: 40 frames per simulated second, 0 to 0.5 s
    const Result r = RunCli(fmt::format("render {} --duration 0.5 --fps 20 --slowmo 2 "
                                        "--width 96 --height 64 --output {}",
                                        testing::kBall, path));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(Probe(path), "96,64,21\n") << extension;
  }
}

TEST(RenderTest, BadInputIsOneLine) {
  const std::string out = ::testing::TempDir() + "/render_bad.mp4";
  Result r = RunCli(fmt::format("render {} --camera top --output {}", FallScene(), out));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, fmt::format("contactlaws: --camera=top is not track, free or a camera of "
                                  "{} (its cameras: side)\n", FallScene()));
  r = RunCli(fmt::format("render {} --camera top --output {}", testing::kBall, out));
  EXPECT_NE(r.output.find("(it has none)"), std::string::npos) << r.output;
  // refused before the run: a folder that is not there, too many frames
  r = RunCli(fmt::format("render {} --output /nonexistent/dir/ball.mp4", testing::kBall));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "contactlaws: --output=/nonexistent/dir/ball.mp4 needs the folder "
                      "/nonexistent/dir, which does not exist\n");
  r = RunCli(fmt::format("render {} --output /nonexistent/frames/", testing::kBall));
  EXPECT_EQ(r.output, "contactlaws: --output=/nonexistent/frames/ needs the folder /nonexistent, "
                      "which does not exist\n");
  r = RunCli(fmt::format("render {} --duration 10 --fps 100 --slowmo 1000 --output {}",
                         testing::kBall, out));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "contactlaws: --duration=10 at --fps=100 and --slowmo=1000 is 1000001 "
                      "frames, more than 100000: shorten the run or lower --fps or --slowmo\n");
  r = RunCli(fmt::format("render {} --output ball.avi", testing::kBall));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "contactlaws: --output=ball.avi is not a format render writes: FILE.mp4 "
                      "(H.264), FILE.gif, or DIR/ (one PNG per frame)\n");
  r = RunCli(fmt::format("render {} --output {} --width 321", testing::kBall, out));
  EXPECT_EQ(r.output, "contactlaws: --width=321 must be even for .mp4 (yuv420p)\n");
  const std::string command = fmt::format("PATH=/nonexistent {} render {} --output {} 2>&1",
                                          CONTACTLAWS_CLI, testing::kBall, out);
  std::FILE* pipe = popen(command.c_str(), "r");
  char line[512] = "";
  if (!std::fgets(line, sizeof(line), pipe)) line[0] = 0;
  pclose(pipe);
  EXPECT_EQ(std::string(line), fmt::format("contactlaws: render --output {} needs ffmpeg, which "
                                           "is not on PATH (Debian package ffmpeg)\n", out));
}

}  // namespace
}  // namespace contactlaws
