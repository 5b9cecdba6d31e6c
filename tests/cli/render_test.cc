// Copyright contactlaws authors.
//
// contactlaws render: a video of the right frame count and size, frames that
// change where the ball moves, and in each frame the pose of the simulated
// state at its time (a falling ball's pixel row against its free-fall
// height projected through the scene's camera); the bad inputs.

#include <png.h>

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli_test_util.h"

namespace contactlaws {
namespace {

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

// A red ball falling before a side camera (looking along +y) over a floor;
// tagged, so that the laws are on.
std::string FallScene() {
  return testing::WriteScene("render_fall", fmt::format(R"(<mujoco>
  <option timestep="1e-4" gravity="0 0 -{g}" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <camera name="side" pos="0 -{d} {ch}" xyaxes="1 0 0 0 0 1" fovy="{fovy}"/>
    <body name="ball" pos="0 0 {z0}">
      <freejoint/>
      <geom name="ball" type="sphere" size="0.1" mass="1" rgba="1 0 0 1"/>
    </body>
  </worldbody>
  <custom><text name="contactlaw:ball-floor"
    data="geom1=ball geom2=floor law=hunt-crossley restitution=0.8 stiffness=1e7"/></custom>
</mujoco>)", fmt::arg("g", kGravity), fmt::arg("d", kCameraDistance),
      fmt::arg("ch", kCameraHeight), fmt::arg("fovy", kFovy), fmt::arg("z0", kStartHeight)));
}

struct Image {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* at(int x, int y) const { return &rgb[3 * (y * width + x)]; }
};

Image ReadPng(const std::string& path) {
  png_image png = {};
  png.version = PNG_IMAGE_VERSION;
  Image image;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    ADD_FAILURE() << path << ": " << png.message;
    return image;
  }
  png.format = PNG_FORMAT_RGB;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgb.resize(PNG_IMAGE_SIZE(png));
  png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr);
  return image;
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

// The row of a point at height z in the camera's vertical plane.
double ProjectedRow(double z) {
  const double half_view = kCameraDistance * std::tan(0.5 * kFovy * M_PI / 180);
  return 0.5 * kHeight * (1 - (z - kCameraHeight) / half_view);
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
  EXPECT_EQ(r.output, fmt::format("contactlaws: --camera=top is not a camera of {} (its "
                                  "cameras: side)\n", FallScene()));
  r = RunCli(fmt::format("render {} --camera top --output {}", testing::kBall, out));
  EXPECT_NE(r.output.find("it has none"), std::string::npos) << r.output;
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
