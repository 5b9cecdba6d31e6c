// Copyright contactlaws authors.

#include "render/contact_marks.h"

#include <algorithm>
#include <map>

namespace contactlaws::render {
namespace {

constexpr float kDiscRgba[4] = {1.0f, 0.85f, 0.1f, 1.0f};     // yellow
constexpr float kNormalRgba[4] = {0.95f, 0.2f, 0.6f, 1.0f};   // magenta
constexpr float kFrictionRgba[4] = {0.1f, 0.8f, 0.95f, 1.0f}; // cyan
// fractions of the body's size
constexpr double kDiscRadius = 0.05;
constexpr double kDiscHalfThickness = 0.005;
constexpr double kArrowRadius = 0.015;

// The next free geom of scene; none when it is full.
mjvGeom* NextGeom(mjvScene* scene) {
  if (scene->ngeom >= scene->maxgeom) return nullptr;
  return scene->geoms + scene->ngeom++;
}

void AddDisc(const double pos[3], const double normal[3], double size, mjvScene* scene) {
  mjvGeom* geom = NextGeom(scene);
  if (!geom) return;
  double quat[4], mat[9];
  mju_quatZ2Vec(quat, normal);
  mju_quat2Mat(mat, quat);
  const double disc[3] = {kDiscRadius * size, kDiscRadius * size, kDiscHalfThickness * size};
  mjv_initGeom(geom, mjGEOM_CYLINDER, disc, pos, mat, kDiscRgba);
  geom->category = mjCAT_DECOR;
}

// An arrow from pos along force, length scale |force| up to longest.
void AddArrow(const double pos[3], const double force[3], double scale, double longest,
              double radius, const float rgba[4], mjvScene* scene) {
  const double norm = mju_norm3(force);
  const double length = std::min(scale * norm, longest);
  if (!(length > 0)) return;
  mjvGeom* geom = NextGeom(scene);
  if (!geom) return;
  mjv_initGeom(geom, mjGEOM_ARROW, nullptr, nullptr, nullptr, rgba);
  geom->category = mjCAT_DECOR;
  // MuJoCo's arrow covers half its connector (its model spans size[2] / 2;
  // measured on 2.2.2: a 0.49 m connector drew 0.235 m)
  const double k = 2 * length / norm;
  mjv_makeConnector(geom, mjGEOM_ARROW, radius, pos[0], pos[1], pos[2], pos[0] + k * force[0],
                    pos[1] + k * force[1], pos[2] + k * force[2]);
}

// The body a pair's forces are drawn on: body[1], which the forces act on,
// unless only body[0] moves.
int DrawnOn(const GeomPair& pair, const MovingBodies& moving) {
  return moving.Moves(pair.body[1]) || !moving.Moves(pair.body[0]) ? pair.body[1] : pair.body[0];
}

}  // namespace

void AddContactMarks(const Simulation& sim, const MovingBodies& moving,
                     std::optional<double> force_scale, mjvScene* scene) {
  // per pair: the points' forces summed, at their centre of pressure
  struct Resultant {
    double weighted_pos[3] = {0, 0, 0};  // sum of pos * normal force
    double mean_pos[3] = {0, 0, 0};      // where a pair without normal force draws
    double normal[3] = {0, 0, 0};
    double friction[3] = {0, 0, 0};
    double pressure = 0;  // sum of the normal forces
    int points = 0;
  };
  std::map<int, Resultant> pairs;
  const std::vector<GeomPair>& geom_pairs = sim.contact_model().pairs();
  for (const PointEvaluation& point : sim.contacts().latest()) {
    const int drawn_on = DrawnOn(geom_pairs[point.pair], moving);
    const double size = moving.Size(drawn_on);
    if (!(size > 0)) continue;
    AddDisc(point.pos, point.normal, size, scene);
    Resultant& r = pairs[point.pair];
    const double force = std::max(point.force, 0.0);
    mju_addToScl3(r.weighted_pos, point.pos, force);
    mju_addTo3(r.mean_pos, point.pos);
    mju_addToScl3(r.normal, point.normal, force);
    mju_addTo3(r.friction, point.friction);
    r.pressure += force;
    ++r.points;
  }
  for (const auto& [pair, r] : pairs) {
    const int drawn_on = DrawnOn(geom_pairs[pair], moving);
    const double size = moving.Size(drawn_on);
    const double sign = drawn_on == geom_pairs[pair].body[1] ? 1 : -1;
    double pos[3], normal[3], friction[3];
    if (r.pressure > 0) {
      mju_scl3(pos, r.weighted_pos, 1 / r.pressure);
    } else {
      mju_scl3(pos, r.mean_pos, 1.0 / r.points);
    }
    mju_scl3(normal, r.normal, sign);
    mju_scl3(friction, r.friction, sign);
    const double scale = force_scale ? *force_scale : moving.ArrowScale(drawn_on);
    const double longest = force_scale ? mjMAXVAL : kMaxArrowSizes * size;
    AddArrow(pos, normal, scale, longest, kArrowRadius * size, kNormalRgba, scene);
    AddArrow(pos, friction, scale, longest, kArrowRadius * size, kFrictionRgba, scene);
  }
}

}  // namespace contactlaws::render
