// Copyright contactlaws authors.

#include "render/frame_renderer.h"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"
#include "render/contact_marks.h"

namespace contactlaws::render {
namespace {

// Room in the scene for the model's geoms, MuJoCo's decorations and our
// marks (mujoco-simulate uses 2000 too).
constexpr int kMaxSceneGeoms = 2000;
// The moving bodies' opacity: solid enough to read as bodies, clear enough
// for the contact marks under and inside them.
constexpr float kBodyAlpha = 0.7f;

// The tracking camera frames the bodies below the overlay, which takes at
// most this share of the height (more tags than that are drawn over).
constexpr double kMaxOverlayShare = 0.4;
// The overlay's font, % of MuJoCo's base size (one of mjtFontScale): 100
// below 400 rows, 150 from 400 (640 x 480), 50 more per 300 rows, up to 300.
int FontScale(int height) { return std::clamp(100 + 50 * ((height - 100) / 300), 100, 300); }

std::string LastRestitution(const Simulation& sim, int tag) {
  const std::vector<Episode>& impacts = sim.contacts().impacts();
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
  throw Error(fmt::format("--camera={} is not track, free or a camera of {} ({})", name, source,
                          m->ncam ? "its cameras: " + cameras : "it has none"));
}

void FrameRenderer::Prepare(mjModel* m, const FrameOptions& options) {
  m->vis.global.offwidth = std::max(m->vis.global.offwidth, options.width);
  m->vis.global.offheight = std::max(m->vis.global.offheight, options.height);
}

FrameRenderer::FrameRenderer(const Simulation& sim, const FrameOptions& options,
                             const TrackedRun& run)
    : options_(options), run_(run) {
  const mjModel* m = sim.model();
  mjv_defaultScene(&scene_);
  mjv_makeScene(m, &scene_, kMaxSceneGeoms);
  mjr_defaultContext(&context_);
  mjr_makeContext(m, &context_, FontScale(options.height));
  mjr_setBuffer(mjFB_OFFSCREEN, &context_);
  mjv_defaultOption(&option_);
  mjv_defaultFreeCamera(m, &camera_);
  if (options.named()) {
    camera_.type = mjCAMERA_FIXED;
    camera_.fixedcamid = FindCamera(m, sim.source(), options.camera);
  }
  flipped_.resize(3 * static_cast<size_t>(options.width) * options.height);
}

FrameRenderer::~FrameRenderer() {
  mjr_freeContext(&context_);
  mjv_freeScene(&scene_);
}

// The moving bodies' geoms at kBodyAlpha of their opacity.
void FrameRenderer::SeeThrough(const mjModel* m) {
  for (int i = 0; i < scene_.ngeom; ++i) {
    mjvGeom& geom = scene_.geoms[i];
    if (geom.objtype == mjOBJ_GEOM && moving_->Moves(m->geom_bodyid[geom.objid])) {
      geom.rgba[3] *= kBodyAlpha;
    }
  }
}

// time, slow motion (unless 1); per tag: law, restitution, last e_post
void FrameRenderer::Overlay(const Simulation& sim) {
  std::string titles = "time";
  std::string values = fmt::format("{:.4f} s", sim.time());
  if (options_.slowmo != 1) {
    titles += "\nslow motion";
    values += fmt::format("\n{:g}x", options_.slowmo);
  }
  const std::vector<PairTag>& tags = sim.contact_model().tags();
  for (int t = 0; t < static_cast<int>(tags.size()); ++t) {
    titles += fmt::format("\n{}", tags[t].label);
    values += fmt::format("\n{}", LawName(tags[t].law));
    if (!IsElastic(tags[t].law)) values += fmt::format("   e = {}", tags[t].restitution);
    values += fmt::format("   e_post {}", LastRestitution(sim, t));
  }
  const mjrRect viewport = {0, 0, options_.width, options_.height};
  mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport, titles.c_str(), values.c_str(),
              &context_);
}

void FrameRenderer::Draw(Simulation* sim, std::vector<unsigned char>* rgb) {
  const mjModel* m = sim->model();
  mjData* d = sim->data();
  if (!moving_) moving_.emplace(m, d);
  if (options_.tracks()) {
    // the overlay's lines (Overlay's) and the half line of its border
    const double lines =
        1.5 + (options_.slowmo != 1) + sim->contact_model().tags().size();
    const double top = std::min(kMaxOverlayShare, lines * context_.charHeight / options_.height);
    AimTrackingCamera(m, run_, moving_->Extent(d),
                      static_cast<double>(options_.width) / options_.height, top, &camera_);
  }
  mjv_updateScene(m, d, &option_, nullptr, &camera_, mjCAT_ALL, &scene_);
  SeeThrough(m);
  AddContactMarks(*sim, *moving_, options_.force_scale, &scene_);
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
