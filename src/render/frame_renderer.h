// Copyright contactlaws authors.
//
// One frame of a Simulation drawn with MuJoCo's own renderer (mjv_*, mjr_*)
// into an offscreen buffer: the scene, the tagged contact points (appended to
// d->contact, as mujoco-simulate shows them with the plugin), an arrow per
// point for our normal force (MuJoCo draws forces only for contacts in its
// solver), and an overlay: the time, each tag's law and restitution, and the
// e_post of its last closed contact episode.

#ifndef CONTACTLAWS_RENDER_FRAME_RENDERER_H_
#define CONTACTLAWS_RENDER_FRAME_RENDERER_H_

#include <optional>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/simulation.h"
#include "contactlaws/visible_contacts.h"
#include "render/offscreen_gl.h"

namespace contactlaws::render {

struct FrameOptions {
  int width = 640;   // pixels
  int height = 480;  // pixels
  // a camera of the scene by name; none: MuJoCo's free camera of the model
  std::optional<std::string> camera;
  // arrow length per newton, m/N; none: MuJoCo's own, vis.map.force / meanmass
  std::optional<double> force_scale;
};

// The camera of m named name; Error listing the scene's cameras otherwise.
int FindCamera(const mjModel* m, const std::string& source, const std::string& name);

class FrameRenderer {
 public:
  // m's vis.global.offwidth/offheight must hold the frame (see Prepare).
  FrameRenderer(const Simulation& sim, const FrameOptions& options);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // Sizes m's offscreen buffer for options (before the Simulation copies it).
  static void Prepare(mjModel* m, const FrameOptions& options);

  // Draws the current state of sim (after mj_forward: Simulation::Sample);
  // rgb gets width x height x 3 bytes, top row first.
  void Draw(Simulation* sim, std::vector<unsigned char>* rgb);

 private:
  void AddForceArrows(const Simulation& sim);
  void AddArrow(const mjModel* m, const double pos[3], const double force[3],
                const float rgba[4]);
  void Overlay(const Simulation& sim);

  FrameOptions options_;
  OffscreenGl gl_;
  mjvScene scene_;
  mjrContext context_;
  mjvCamera camera_;
  mjvOption option_;
  double force_scale_ = 0;
  VisibleContactsOverflow overflow_;
  std::vector<unsigned char> flipped_;
};

}  // namespace contactlaws::render

#endif  // CONTACTLAWS_RENDER_FRAME_RENDERER_H_
