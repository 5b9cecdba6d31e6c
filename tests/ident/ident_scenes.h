// Copyright contactlaws authors.
//
// Scenes and trajectories of the identification tests: a cube tossed onto a
// board (mjcf/cube_toss.xml's cube), and measured data made in memory.

#ifndef CONTACTLAWS_TESTS_IDENT_SCENES_H_
#define CONTACTLAWS_TESTS_IDENT_SCENES_H_

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "contactlaws/contactlaws.h"

namespace contactlaws::testing {

// The cube of the tosses on a board, with the tag's words.
inline Scene CubeScene(const std::string& tag) {
  const std::string xml = fmt::format(R"(
<mujoco model="cube">
  <option timestep="6.756756756756757e-4" integrator="RK4"/>
  <worldbody>
    <geom name="board" type="plane" size="1 1 0.1"/>
    <body name="cube" pos="0 0 0.3">
      <freejoint name="cube_free"/>
      <inertial pos="0 0 0" mass="0.37" diaginertia="8.1e-4 8.1e-4 8.1e-4"/>
      <geom name="cube" type="box" size="0.0524 0.0524 0.0524"/>
    </body>
    <body name="arm" pos="1 0 0.5">
      <joint name="hinge" type="hinge" axis="0 1 0"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.2" size="0.01" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
  <custom>
    <text name="contactlaw:cube-board" data="geom1=cube geom2=board {}"/>
  </custom>
</mujoco>)",
                                      tag);
  return Scene("cube.xml", LoadModelString(xml, "cube.xml"));
}

inline const std::vector<std::string>& CubeColumns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> c;
    for (const char* q : kBodyQuantities) c.push_back(fmt::format("cube.{}", q));
    return c;
  }();
  return columns;
}

// count tosses of the README's ranges (drawn from seed): each starts at
// 0.25 m, falling at 0.3-1.7 m/s, sideways at about 1.1 m/s, spinning at
// 0.5-11 rad/s, at a random orientation; samples at 148 Hz over 0.7 s. Only
// the first sample is set: the others are copies, to be simulated over.
inline MeasuredData TossStarts(int count, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  MeasuredData data;
  data.source = "tosses";
  data.columns = CubeColumns();
  for (int i = 0; i < count; ++i) {
    MeasuredTrajectory t;
    t.name = fmt::format("{}", i);
    double q[4] = {u(random) - 0.5, u(random) - 0.5, u(random) - 0.5, u(random) - 0.5};
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    const double heading = 2 * M_PI * u(random);
    const double spin = 0.5 + 10.5 * u(random);
    const double axis[3] = {u(random) - 0.5, u(random) - 0.5, u(random) - 0.5};
    const double axis_norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    std::vector<double> first = {0.0, 0.0, 0.25, q[0] / norm, q[1] / norm, q[2] / norm,
                                 q[3] / norm, 1.1 * std::cos(heading), 1.1 * std::sin(heading),
                                 -(0.3 + 1.4 * u(random))};
    for (double a : axis) first.push_back(spin * a / axis_norm);
    for (int k = 0; k < 104; ++k) {
      t.time.push_back(k / 148.0);
      t.values.insert(t.values.end(), first.begin(), first.end());
    }
    data.trajectories.push_back(std::move(t));
  }
  return data;
}

// The data's trajectories simulated in scene (from their first sample): the
// simulated samples as measured data.
inline MeasuredData Simulated(const Scene& scene, const MeasuredData& starts,
                              ReplayOptions options) {
  options.keep_trajectories = true;
  const Replay replay(scene, starts);
  const std::vector<ReplayedTrajectory> replayed = replay.Run(options);
  MeasuredData out = starts;
  for (size_t i = 0; i < replayed.size(); ++i) out.trajectories[i].values = replayed[i].simulated;
  return out;
}

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_IDENT_SCENES_H_
