// Copyright contactlaws authors.

#include "render/frame_renderer.h"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "contactlaws/error.h"

namespace contactlaws::render {
namespace {

// Room in the scene for the model's geoms, MuJoCo's decorations and our
// arrows (mujoco-simulate uses 2000 too).
constexpr int kMaxSceneGeoms = 2000;
// The overlay's font, % of MuJoCo's base size.
constexpr int kFontScale = 100;

std::string LastRestitution(const Simulation& sim, int tag) {
  const std::vector<Impact>& impacts = sim.contacts().impacts();
  for (auto it = impacts.rbegin(); it != impacts.rend(); ++it) {
    if (it->tag == tag && !it->open) return fmt::format("{:.4f}", it->restitution_post());
  }
  return "-";
}

}  // namespace

int FindCamera(const mjModel* m, const std::string& source, const std::string& name) {
  const int id = mj_name2id(m, mjOBJ_CAMERA, name.c_str());
  if (id >= 0) return id;
  std::string cameras;
  for (int i = 0; i < m->ncam; ++i) {
    const char* camera = m->names + m->name_camadr[i];
    cameras += fmt::format("{}{}", i ? ", " : "", *camera ? camera : fmt::format("#{}", i));
  }
  throw Error(fmt::format("--camera={} is not a camera of {} ({})", name, source,
                          m->ncam ? "its cameras: " + cameras
                                  : "it has none; without --camera the free camera is used"));
}

void FrameRenderer::Prepare(mjModel* m, const FrameOptions& options) {
  m->vis.global.offwidth = std::max(m->vis.global.offwidth, options.width);
  m->vis.global.offheight = std::max(m->vis.global.offheight, options.height);
}

FrameRenderer::FrameRenderer(const Simulation& sim, const FrameOptions& options)
    : options_(options) {
  const mjModel* m = sim.model();
  mjv_defaultScene(&scene_);
  mjv_makeScene(m, &scene_, kMaxSceneGeoms);
  mjr_defaultContext(&context_);
  mjr_makeContext(m, &context_, kFontScale);
  mjr_setBuffer(mjFB_OFFSCREEN, &context_);
  mjv_defaultOption(&option_);
  option_.flags[mjVIS_CONTACTPOINT] = 1;
  // the contact is under the body that makes it: moving bodies see-through
  option_.flags[mjVIS_TRANSPARENT] = 1;
  mjv_defaultFreeCamera(m, &camera_);
  if (options.camera) {
    camera_.type = mjCAMERA_FIXED;
    camera_.fixedcamid = FindCamera(m, sim.source(), *options.camera);
  }
  force_scale_ = options.force_scale ? *options.force_scale
                                     : m->vis.map.force / m->stat.meanmass;
  flipped_.resize(3 * static_cast<size_t>(options.width) * options.height);
}

FrameRenderer::~FrameRenderer() {
  mjr_freeContext(&context_);
  mjv_freeScene(&scene_);
}

// An arrow from pos along force (a world vector, N) scaled by force_scale_,
// in rgba; none when the scene is full or the force is nil.
void FrameRenderer::AddArrow(const mjModel* m, const double pos[3], const double force[3],
                             const float rgba[4]) {
  const double length = force_scale_ * mju_norm3(force);
  if (scene_.ngeom >= scene_.maxgeom || !(length > 0)) return;
  mjvGeom* geom = scene_.geoms + scene_.ngeom++;
  mjv_initGeom(geom, mjGEOM_ARROW, nullptr, nullptr, nullptr, rgba);
  geom->category = mjCAT_DECOR;
  const double width = m->vis.scale.forcewidth * m->stat.meansize;
  mjv_makeConnector(geom, mjGEOM_ARROW, width, pos[0], pos[1], pos[2],
                    pos[0] + force_scale_ * force[0], pos[1] + force_scale_ * force[1],
                    pos[2] + force_scale_ * force[2]);
}

// Arrows per tagged point, from the point: the normal force on geom2 (the
// normal points from geom1 to geom2; the force pushes them apart) in MuJoCo's
// contact-force colour, the friction force on it in its friction colour.
void FrameRenderer::AddForceArrows(const Simulation& sim) {
  const mjModel* m = sim.model();
  for (const PointEvaluation& point : sim.contacts().latest()) {
    double normal[3];
    mju_scl3(normal, point.normal, std::max(point.force, 0.0));
    AddArrow(m, point.pos, normal, m->vis.rgba.contactforce);
    AddArrow(m, point.pos, point.friction, m->vis.rgba.contactfriction);
  }
}

// time; per tag: law, restitution, last e_post
void FrameRenderer::Overlay(const Simulation& sim) {
  std::string titles = "time";
  std::string values = fmt::format("{:.4f} s", sim.time());
  const std::vector<PairTag>& tags = sim.contact_model().tags();
  for (int t = 0; t < static_cast<int>(tags.size()); ++t) {
    titles += fmt::format("\n{}", tags[t].label);
    values += fmt::format("\n{}", LawName(tags[t].law));
    if (!IsElastic(tags[t].law)) values += fmt::format(" e = {}", tags[t].restitution);
    values += fmt::format("  e_post {}", LastRestitution(sim, t));
  }
  const mjrRect viewport = {0, 0, options_.width, options_.height};
  mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport, titles.c_str(), values.c_str(),
              &context_);
}

void FrameRenderer::Draw(Simulation* sim, std::vector<unsigned char>* rgb) {
  const mjModel* m = sim->model();
  mjData* d = sim->data();
  const int ncon = d->ncon;
  AppendVisibleContacts(sim->contacts(), d, &overflow_);
  mjv_updateScene(m, d, &option_, nullptr, &camera_, mjCAT_ALL, &scene_);
  d->ncon = ncon;  // the points are drawn: the data as the step left it
  AddForceArrows(*sim);
  const mjrRect viewport = {0, 0, options_.width, options_.height};
  mjr_render(viewport, &scene_, &context_);
  Overlay(*sim);
  mjr_readPixels(flipped_.data(), nullptr, viewport, &context_);
  // OpenGL's rows go bottom up
  const size_t row = 3 * static_cast<size_t>(options_.width);
  rgb->resize(flipped_.size());
  for (int y = 0; y < options_.height; ++y) {
    std::memcpy(rgb->data() + y * row, flipped_.data() + (options_.height - 1 - y) * row, row);
  }
}

}  // namespace contactlaws::render
