// Copyright contactlaws authors.
//
// ball_box_scene: writes, compares and test-runs the many-ball scene.
//
//   ball_box_scene write N FILE    the scene of N balls (mjcf/ball_box_64.xml is N = 64)
//   ball_box_scene diff N FILE     exit 1 unless FILE is byte for byte the scene of N balls
//   ball_box_scene run FILE T      T s with the contact laws, then T s with MuJoCo's own
//                                  contact: exit 1 on any MuJoCo warning, a ball outside
//                                  the box, or a non-finite state

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include "ball_box.h"
#include "contactlaws/contactlaws.h"

namespace {

using contactlaws::bench::BallBoxXml;

std::vector<std::string>& Warnings() {
  static std::vector<std::string> warnings;
  return warnings;
}

void RecordWarning(const char* message) { Warnings().emplace_back(message); }

int Usage() {
  fmt::print(stderr,
             "usage: ball_box_scene write N FILE | diff N FILE | run FILE SECONDS\n");
  return 2;
}

int Write(int balls, const std::string& path) {
  std::ofstream file(path, std::ios::binary);
  file << BallBoxXml(balls);
  file.close();
  if (!file) {
    fmt::print(stderr, "ball_box_scene: could not write {}\n", path);
    return 1;
  }
  return 0;
}

int Diff(int balls, const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (!file.good() && !file.eof()) {
    fmt::print(stderr, "ball_box_scene: could not read {}\n", path);
    return 1;
  }
  if (text != BallBoxXml(balls)) {
    fmt::print(stderr,
               "ball_box_scene: {} is not the generator's scene of {} balls: edit "
               "tests/bench/ball_box.cc and run `ball_box_scene write {} {}`\n",
               path, balls, balls, path);
    return 1;
  }
  return 0;
}

// Checks d after a run: every ball inside the box (sunk at most tolerance m
// into a wall or the floor), finite, no warning. Returns the number of
// problems, printed.
int CheckState(const mjModel* m, const mjData* d, const std::string& what, double tolerance) {
  // the box from its walls, the balls' radius from their geoms
  const int wall = mj_name2id(m, mjOBJ_GEOM, "wall_px");
  if (wall < 0) {
    fmt::print(stderr, "{}: no geom wall_px\n", what);
    return 1;
  }
  const double half_width = m->geom_pos[3 * wall];
  int problems = 0;
  double deepest = 0;  // m, the largest penetration of a wall or the floor
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_type[g] != mjGEOM_SPHERE) continue;
    const double r = m->geom_size[3 * g];
    const mjtNum* p = d->geom_xpos + 3 * g;
    const double sink = std::max({std::fabs(p[0]) + r - half_width,
                                  std::fabs(p[1]) + r - half_width, r - p[2]});
    deepest = std::max(deepest, sink);
    if (!std::isfinite(p[0] + p[1] + p[2]) || sink > tolerance) {
      fmt::print(stderr, "{}: {} at ({:.4f}, {:.4f}, {:.4f}) is outside the box\n", what,
                 contactlaws::ObjectName(m, mjOBJ_GEOM, g), p[0], p[1], p[2]);
      ++problems;
    }
  }
  for (int i = 0; i < mjNWARNING; ++i) {
    if (d->warning[i].number > 0) {
      fmt::print(stderr, "{}: MuJoCo warning {} raised {} times\n", what, i,
                 d->warning[i].number);
      ++problems;
    }
  }
  for (const std::string& w : Warnings()) {
    fmt::print(stderr, "{}: MuJoCo warning: {}\n", what, w);
    ++problems;
  }
  Warnings().clear();
  fmt::print("{}: t = {:.3f} s, deepest into a wall or the floor {:.3g} mm, ncon {}\n", what,
             d->time, 1e3 * deepest, d->ncon);
  return problems;
}

int Run(const std::string& path, double seconds) {
  mju_user_warning = RecordWarning;
  int problems = 0;
  {
    contactlaws::Simulation sim(contactlaws::LoadModelFile(path), path);
    while (sim.time() < seconds) sim.Step();
    // the laws' contacts are at most ~1 mm deep at these speeds
    problems += CheckState(sim.model(), sim.data(), path + " (contact laws)", 0.005);
    int episodes = 0;
    for (const contactlaws::Episode& impact : sim.contacts().impacts()) episodes += !impact.open;
    fmt::print("{} (contact laws): {} contact episodes ended\n", path, episodes);
  }
  {
    // no ContactData alive: MuJoCo's own contact, the tags inert
    contactlaws::UniqueModel m = contactlaws::LoadModelFile(path);
    contactlaws::UniqueData d(mj_makeData(m.get()));
    if (m->nkey > 0) mj_resetDataKeyframe(m.get(), d.get(), 0);
    while (d->time < seconds) mj_step(m.get(), d.get());
    // MuJoCo's default soft contact (solref 0.02 s) lets a ball at 1.5 m/s
    // sink ~1 cm: inside means less than half the radius
    problems += CheckState(m.get(), d.get(), path + " (MuJoCo's contact)", 0.025);
  }
  return problems ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) return Usage();
  const std::string command = argv[1];
  try {
    if (command == "write") return Write(std::stoi(argv[2]), argv[3]);
    if (command == "diff") return Diff(std::stoi(argv[2]), argv[3]);
    if (command == "run") return Run(argv[2], std::stod(argv[3]));
  } catch (const std::exception& e) {
    fmt::print(stderr, "ball_box_scene: {}\n", e.what());
    return 2;
  }
  return Usage();
}
