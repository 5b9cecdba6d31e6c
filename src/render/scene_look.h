// Copyright contactlaws authors.
//
// The look of MuJoCo's sample models (and of the shipped scenes) for a
// scene that has no visuals of its own: most hand-written and converted
// scenes, which MuJoCo's defaults draw as grey bodies on a grey floor before
// a grey background. Decided per element, and a scene's own is never
// replaced:
//   sky     a gradient skybox, when the scene has no skybox texture (and
//           the haze, when at MuJoCo's default, that of the sky);
//   light   a directional key light casting shadows, when the scene has no
//           light (and the headlight and shadow map size, when at MuJoCo's
//           defaults, those of the shipped scenes);
//   ground  a checker material on each plane that has no material and
//           MuJoCo's default colour; its squares 1, 2 or 5 x 10^k m, about
//           kSquareSizes of the moving geoms' median diameter;
//   bodies  a colour per body (a palette, in body order) on each other geom
//           that has no material and MuJoCo's default colour.
// What is added is visual only: textures, a material and a light appended
// after the scene's own (whose ids are unchanged), geom colours and
// materials, and visual options: the dressed model steps bit for bit as
// the scene's.

#ifndef CONTACTLAWS_RENDER_SCENE_LOOK_H_
#define CONTACTLAWS_RENDER_SCENE_LOOK_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/contact_model.h"

namespace contactlaws::render {

struct LookPlan {
  bool sky = false;            // a skybox is added
  bool light = false;          // a key light is added
  std::vector<int> floors;     // planes that get the checker
  std::vector<int> painted;    // geoms that get their body's colour
  double square = 0;           // the checker's square, m

  bool empty() const { return !sky && !light && floors.empty() && painted.empty(); }
  // one line: what is added ("sky, key light, checker on 1 plane, colours on 2 geoms")
  std::string Describe() const;
};

// What m (compiled from a scene) lacks, by the rule above.
LookPlan PlanLook(const mjModel* m);

// The scene's model with plan's additions (not empty): its file (path)
// compiled again with them, the arena's sizes set after compile (njmax,
// nconmax, nstack) carried over from m. Error when the file cannot be read
// again or compiled with them.
UniqueModel Dressed(const mjModel* m, const std::string& path, const LookPlan& plan);

}  // namespace contactlaws::render

#endif  // CONTACTLAWS_RENDER_SCENE_LOOK_H_
