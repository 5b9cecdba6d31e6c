// Copyright contactlaws authors.

#include "render/scene_look.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"

namespace contactlaws::render {
namespace {

// The names of what is added: a scene's own names never start so.
constexpr char kSky[] = "contactlaws_look_sky";
constexpr char kChecker[] = "contactlaws_look_checker";
constexpr char kFloor[] = "contactlaws_look_floor";
constexpr char kKeyLight[] = "contactlaws_look_key";

// The checker's square is about this many of the moving geoms' median
// bounding diameter: large enough to read as a floor, small enough that a
// body travelling its own size is seen to move over it (the median, so that
// one long geom, a plank or a pole, does not make the squares of a ball
// rolling on it larger than the floor).
constexpr double kSquareSizes = 5;
// Without moving geoms: this share of the model's extent.
constexpr double kSquareExtentShare = 0.1;

// The shipped scenes' look (mjcf/die_throw.xml and the others).
constexpr float kHeadlightAmbient = 0.3f;
constexpr float kHeadlightDiffuse = 0.5f;
constexpr float kHeadlightSpecular = 0.1f;
constexpr float kHaze[4] = {0.15f, 0.25f, 0.35f, 1};
constexpr int kShadowSize = 2048;  // half MuJoCo's: a frame costs less

// A body's colour: distinct hues, none of them the floor's blue-grey.
constexpr std::array<std::array<float, 3>, 8> kPalette = {{{0.85f, 0.33f, 0.10f},
                                                           {0.93f, 0.69f, 0.13f},
                                                           {0.47f, 0.67f, 0.19f},
                                                           {0.30f, 0.75f, 0.93f},
                                                           {0.64f, 0.30f, 0.70f},
                                                           {0.90f, 0.90f, 0.85f},
                                                           {0.75f, 0.15f, 0.20f},
                                                           {0.20f, 0.55f, 0.55f}}};
// The world's own geoms (a table, walls): wood.
constexpr std::array<float, 3> kWorldColour = {0.55f, 0.4f, 0.25f};

// MuJoCo's defaults, from a model that sets nothing: a value equal to one
// of them is not the scene's own.
const mjModel* Defaults() {
  static const UniqueModel model =
      LoadModelString("<mujoco><worldbody><geom size='1'/></worldbody></mujoco>", "defaults.xml");
  return model.get();
}

bool DefaultColour(const mjModel* m, int g) {
  return std::equal(m->geom_rgba + 4 * g, m->geom_rgba + 4 * g + 4, Defaults()->geom_rgba);
}

bool Equal3(const float* a, const float* b) { return std::equal(a, a + 3, b); }

// 1, 2 or 5 x 10^k, the largest not above length
double RoundDown125(double length) {
  const double decade = std::pow(10.0, std::floor(std::log10(length)));
  for (double step : {5.0, 2.0}) {
    if (step * decade <= length) return step * decade;
  }
  return decade;
}

double SquareSize(const mjModel* m) {
  std::vector<double> radii;
  for (int g = 0; g < m->ngeom; ++g) {
    const int body = m->geom_bodyid[g];
    if (m->body_weldid[body] != 0 && m->geom_type[g] != mjGEOM_PLANE && m->geom_rbound[g] > 0) {
      radii.push_back(m->geom_rbound[g]);
    }
  }
  // the lower median
  const auto median = radii.begin() + (radii.size() - 1) / 2;
  if (!radii.empty()) std::nth_element(radii.begin(), median, radii.end());
  const double length =
      radii.empty() ? kSquareExtentShare * m->stat.extent : kSquareSizes * 2 * *median;
  return RoundDown125(length > 0 ? length : 1);
}

// The elements to add, as one MJCF fragment inside <mujoco>.
std::string Additions(const LookPlan& plan) {
  std::string assets;
  if (plan.sky) {
    assets += fmt::format(R"(<texture name="{}" type="skybox" builtin="gradient" )"
                          R"(rgb1="0.4 0.6 0.8" rgb2="0 0 0" width="64" height="64"/>)",
                          kSky);
  }
  if (!plan.floors.empty()) {
    // a builtin checker has 2 x 2 squares; uniform on a plane: texrepeat per metre
    assets += fmt::format(R"(<texture name="{}" type="2d" builtin="checker" rgb1="0.2 0.3 0.4" )"
                          R"(rgb2="0.1 0.2 0.3" width="64" height="64"/>)"
                          R"(<material name="{}" texture="{}" texrepeat="{:.17g} {:.17g}" )"
                          R"(texuniform="true" reflectance="0.2"/>)",
                          kChecker, kFloor, kChecker, 1 / plan.square, 1 / plan.square);
  }
  std::string xml;
  if (!assets.empty()) xml += "<asset>" + assets + "</asset>";
  if (plan.light) {
    xml += fmt::format(R"(<worldbody><light name="{}" pos="0 0 10" dir="0.3 0.2 -1" )"
                       R"(directional="true" diffuse="0.5 0.5 0.5" castshadow="true"/>)"
                       R"(</worldbody>)",
                       kKeyLight);
  }
  return xml;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(fmt::format("{}: cannot be read again to add its look", path));
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The visual options and the colours, set on the compiled model.
void SetVisuals(mjModel* m, const LookPlan& plan) {
  const mjModel* defaults = Defaults();
  if (plan.light) {
    auto& head = m->vis.headlight;
    const auto& plain = defaults->vis.headlight;
    if (Equal3(head.ambient, plain.ambient) && Equal3(head.diffuse, plain.diffuse) &&
        Equal3(head.specular, plain.specular)) {
      std::fill_n(head.ambient, 3, kHeadlightAmbient);
      std::fill_n(head.diffuse, 3, kHeadlightDiffuse);
      std::fill_n(head.specular, 3, kHeadlightSpecular);
    }
    if (m->vis.quality.shadowsize == defaults->vis.quality.shadowsize) {
      m->vis.quality.shadowsize = kShadowSize;
    }
  }
  if (plan.sky && std::equal(m->vis.rgba.haze, m->vis.rgba.haze + 4, defaults->vis.rgba.haze)) {
    std::copy(kHaze, kHaze + 4, m->vis.rgba.haze);
  }
  const int floor = mj_name2id(m, mjOBJ_MATERIAL, kFloor);
  for (int g : plan.floors) m->geom_matid[g] = floor;
  for (int g : plan.painted) {
    const int body = m->geom_bodyid[g];
    const std::array<float, 3>& rgb =
        body == 0 ? kWorldColour : kPalette[(body - 1) % kPalette.size()];
    std::copy(rgb.begin(), rgb.end(), m->geom_rgba + 4 * g);
  }
}

}  // namespace

std::string LookPlan::Describe() const {
  std::vector<std::string> parts;
  if (sky) parts.push_back("sky");
  if (light) parts.push_back("key light");
  if (!floors.empty()) {
    parts.push_back(fmt::format("checker ({:g} m squares) on {} plane{}", square, floors.size(),
                                floors.size() == 1 ? "" : "s"));
  }
  if (!painted.empty()) {
    parts.push_back(fmt::format("colours on {} geom{}", painted.size(),
                                painted.size() == 1 ? "" : "s"));
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

LookPlan PlanLook(const mjModel* m) {
  LookPlan plan;
  plan.sky = std::none_of(m->tex_type, m->tex_type + m->ntex,
                          [](int type) { return type == mjTEXTURE_SKYBOX; });
  plan.light = m->nlight == 0;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_matid[g] >= 0 || !DefaultColour(m, g)) continue;
    (m->geom_type[g] == mjGEOM_PLANE ? plan.floors : plan.painted).push_back(g);
  }
  if (!plan.floors.empty()) plan.square = SquareSize(m);
  return plan;
}

UniqueModel Dressed(const mjModel* m, const std::string& path, const LookPlan& plan) {
  std::string xml = ReadFile(path);
  const size_t end = xml.rfind("</mujoco");
  if (end == std::string::npos) {
    throw Error(fmt::format("{}: no </mujoco> to add its look before", path));
  }
  xml.insert(end, Additions(plan));
  // the file's own name: its includes and assets are found beside it
  UniqueModel dressed = LoadModelString(xml, path);
  dressed->njmax = m->njmax;
  dressed->nconmax = m->nconmax;
  dressed->nstack = m->nstack;
  SetVisuals(dressed.get(), plan);
  return dressed;
}

}  // namespace contactlaws::render
