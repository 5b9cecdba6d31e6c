// Copyright contactlaws authors.

#include "auto_scenes.h"

#include <fmt/format.h>

namespace contactlaws::bench {
namespace {

constexpr double kRadius = 0.1;  // m
constexpr double kMass = 10;     // kg

}  // namespace

const char* BallBallPairsName(BallBallPairs pairs) {
  switch (pairs) {
    case BallBallPairs::kUntagged: return "untagged";
    case BallBallPairs::kTagged: return "tagged";
    case BallBallPairs::kMasked: return "masked";
  }
  return "";
}

std::string BallDropXml(BallBallPairs pairs, int per_side) {
  constexpr double kSpacing = 2.0;  // m between centres
  constexpr double kHeight = 5.0;   // m, the centres at the start
  // masked: balls collide with the floor only (contype 1 & conaffinity 2 = 0)
  const char* ball_bits = pairs == BallBallPairs::kMasked ? " contype=\"1\" conaffinity=\"2\"" : "";
  const char* floor_bits = pairs == BallBallPairs::kMasked ? " contype=\"2\" conaffinity=\"1\"" : "";
  std::string xml = fmt::format(
      "<mujoco model=\"ball_drop_{}\">\n"
      "  <option timestep=\"1e-5\" gravity=\"0 0 -9.81\" integrator=\"RK4\"/>\n"
      "  <worldbody>\n"
      "    <geom name=\"floor\" type=\"plane\" size=\"10 10 0.1\" group=\"2\"{}/>\n",
      BallBallPairsName(pairs), floor_bits);
  const double offset = 0.5 * (per_side - 1) * kSpacing;
  for (int i = 0; i < per_side; ++i) {
    for (int j = 0; j < per_side; ++j) {
      const int k = i * per_side + j;
      xml += fmt::format(
          "    <body name=\"ball{}\" pos=\"{} {} {}\"><freejoint/>"
          "<geom type=\"sphere\" size=\"{}\" mass=\"{}\" group=\"1\"{}/></body>\n",
          k, i * kSpacing - offset, j * kSpacing - offset, kHeight, kRadius, kMass, ball_bits);
    }
  }
  xml +=
      "  </worldbody>\n"
      "  <custom>\n"
      "    <text name=\"contactlaw:ball-floor\" "
      "data=\"geom1=group:1 geom2=floor law=hertz stiffness=1.4e8 exponent=1.5\"/>\n";
  if (pairs == BallBallPairs::kTagged) {
    xml +=
        "    <text name=\"contactlaw:ball-ball\" "
        "data=\"geom1=group:1 geom2=group:1 law=hertz stiffness=4.95e7 exponent=1.5\"/>\n";
  }
  xml += "  </custom>\n</mujoco>\n";
  return xml;
}

std::string PileXml(int per_side) {
  constexpr double kGap = 0.01;  // m between neighbours, and above the ground
  const double spacing = 2 * kRadius + kGap;
  std::string xml = fmt::format(
      "<mujoco model=\"pile_{}\">\n"
      "  <option timestep=\"1e-4\" gravity=\"0 0 -9.81\" integrator=\"RK4\"/>\n"
      "  <worldbody>\n"
      "    <geom name=\"ground\" type=\"plane\" size=\"5 5 0.1\" group=\"2\"/>\n",
      per_side * per_side * per_side);
  const double offset = 0.5 * (per_side - 1) * spacing;
  for (int i = 0; i < per_side; ++i) {
    for (int j = 0; j < per_side; ++j) {
      for (int k = 0; k < per_side; ++k) {
        xml += fmt::format(
            "    <body name=\"ball{}\" pos=\"{:.4f} {:.4f} {:.4f}\"><freejoint/>"
            "<geom type=\"sphere\" size=\"{}\" mass=\"{}\" group=\"1\"/></body>\n",
            (i * per_side + j) * per_side + k, i * spacing - offset, j * spacing - offset,
            kRadius + kGap + k * spacing, kRadius, kMass);
      }
    }
  }
  xml +=
      "  </worldbody>\n"
      "  <custom>\n"
      "    <text name=\"contactlaw:ball-ball\" data=\"geom1=group:1 geom2=group:1 "
      "law=hunt-crossley restitution=0.05 stiffness=1e9 exponent=1.5 friction=none\"/>\n"
      "    <text name=\"contactlaw:ball-ground\" data=\"geom1=group:1 geom2=ground "
      "law=hunt-crossley restitution=0.05 stiffness=1e9 exponent=1.5 friction=none\"/>\n"
      "  </custom>\n</mujoco>\n";
  return xml;
}

}  // namespace contactlaws::bench
