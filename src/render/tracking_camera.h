// Copyright contactlaws authors.
//
// render's default camera (--camera track): MuJoCo's free camera at the
// angles mujoco-simulate opens with (the model's visual/global azimuth and
// elevation: 90 and -45 degrees unless the scene says otherwise), aimed at
// the moving bodies and following them.
//
// What it frames, decided from the whole run (a first pass over it, at the
// frame times): a view box that holds the moving set's box over the run,
// but no more than kSurroundings times the largest the set itself gets in
// any frame, in each direction. The view box is centred on the set as it is
// now, then held inside the run's box. So a set that stays in a small region
// (a bouncing ball, a stack, the belt's block) is seen whole and at rest by
// a camera that hardly moves, and one that travels far for its size (a 2 cm
// die thrown across a table) is followed at a size where it can be seen,
// the floor's checker passing beneath. The distance is one for the run: a
// camera that framed each frame's box alone would zoom as a set spreads
// and gathers, and one that framed the run's box alone would leave the die
// a few pixels.

#ifndef CONTACTLAWS_RENDER_TRACKING_CAMERA_H_
#define CONTACTLAWS_RENDER_TRACKING_CAMERA_H_

#include <mujoco/mujoco.h>

#include "contactlaws/simulation.h"
#include "render/moving_bodies.h"

namespace contactlaws::render {

// The view box spans at most this many times the moving set's largest
// side (its largest over the run): the set fills at least a third of it.
constexpr double kSurroundings = 3.0;

// What the first pass over the run found.
struct TrackedRun {
  Box run;                 // the moving set's box over every frame
  double largest_set = 0;  // the largest side of the set's box in any frame, m

  void Add(const Box& frame);
};

// The first pass: sim advanced as options say, the moving set's box taken at
// every frame time (options.sample_rate); result: how the pass ended.
TrackedRun TrackRun(Simulation* sim, const AdvanceOptions& options, AdvanceResult* result);

// The free camera aimed at the set whose box is now, framing the view box
// in a width / height = aspect frame at the model's vertical field of view,
// below its top fraction top (the overlay's). Without moving bodies:
// MuJoCo's free camera of the model.
void AimTrackingCamera(const mjModel* m, const TrackedRun& run, const Box& now, double aspect,
                       double top, mjvCamera* camera);

}  // namespace contactlaws::render

#endif  // CONTACTLAWS_RENDER_TRACKING_CAMERA_H_
