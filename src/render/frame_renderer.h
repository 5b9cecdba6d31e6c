// Copyright contactlaws authors.
//
// One frame of a Simulation drawn with MuJoCo's own renderer (mjv_*, mjr_*)
// into an offscreen buffer: the scene seen by the tracking camera
// (tracking_camera.h), MuJoCo's free camera or one of the scene's; the moving
// bodies half see-through, so that what happens under them shows; the marks
// of the tagged contact points (contact_marks.h); and an overlay: the time
// and the slow motion, each tag's law and restitution, and the e_post of its
// last closed contact episode.

#ifndef CONTACTLAWS_RENDER_FRAME_RENDERER_H_
#define CONTACTLAWS_RENDER_FRAME_RENDERER_H_

#include <optional>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/simulation.h"
#include "render/moving_bodies.h"
#include "render/offscreen_gl.h"
#include "render/tracking_camera.h"

namespace contactlaws::render {

struct FrameOptions {
  int width = 640;   // pixels
  int height = 480;  // pixels
  // kTrack, kFree (MuJoCo's free camera of the model, as mujoco-simulate
  // opens it), or a camera of the scene by name
  std::string camera = kTrack;
  // arrow length per newton, m/N; none: each body's (contact_marks.h)
  std::optional<double> force_scale;
  double slowmo = 1;  // shown in the overlay

  static constexpr char kTrack[] = "track";
  static constexpr char kFree[] = "free";
  bool tracks() const { return camera == kTrack; }
  bool named() const { return camera != kTrack && camera != kFree; }
};

// The camera of m named name; Error listing the scene's cameras otherwise.
int FindCamera(const mjModel* m, const std::string& source, const std::string& name);

class FrameRenderer {
 public:
  // m's vis.global.offwidth/offheight must hold the frame (see Prepare);
  // run: what the tracking camera frames (TrackRun), when options track.
  FrameRenderer(const Simulation& sim, const FrameOptions& options, const TrackedRun& run = {});
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // Sizes m's offscreen buffer for options (before the Simulation copies it).
  static void Prepare(mjModel* m, const FrameOptions& options);

  // Draws the current state of sim (after mj_forward: Simulation::Sample);
  // rgb gets width x height x 3 bytes, top row first. The bodies' sizes are
  // measured in the first frame drawn.
  void Draw(Simulation* sim, std::vector<unsigned char>* rgb);

 private:
  void SeeThrough(const mjModel* m);
  void Overlay(const Simulation& sim);

  FrameOptions options_;
  TrackedRun run_;
  std::optional<MovingBodies> moving_;
  OffscreenGl gl_;
  mjvScene scene_;
  mjrContext context_;
  mjvCamera camera_;
  mjvOption option_;
  std::vector<unsigned char> flipped_;
};

}  // namespace contactlaws::render

#endif  // CONTACTLAWS_RENDER_FRAME_RENDERER_H_
