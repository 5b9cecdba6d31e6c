// Copyright contactlaws authors.

#include "render/tracking_camera.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace contactlaws::render {
namespace {

// A border around the view box, a fraction of its size on each side.
constexpr double kMargin = 0.1;

}  // namespace

void TrackedRun::Add(const Box& frame) {
  run.Add(frame);
  largest_set = std::max(largest_set, frame.LargestSide());
}

TrackedRun TrackRun(Simulation* sim, const AdvanceOptions& options, AdvanceResult* result) {
  TrackedRun tracked;
  std::optional<MovingBodies> moving;
  *result = Advance(sim, options, [&](const std::vector<double>&) {
    if (!moving) moving.emplace(sim->model(), sim->data());
    tracked.Add(moving->Extent(sim->data()));
  });
  return tracked;
}

void AimTrackingCamera(const mjModel* m, const TrackedRun& run, const Box& now, double aspect,
                       double top, mjvCamera* camera) {
  if (run.run.empty() || now.empty()) {
    mjv_defaultFreeCamera(m, camera);
    return;
  }
  camera->type = mjCAMERA_FREE;
  camera->azimuth = m->vis.global.azimuth;
  camera->elevation = m->vis.global.elevation;
  // the view box: the run's, at most kSurroundings sets wide in each
  // direction, centred on the set now and held inside the run's box
  const double most = 0.5 * kSurroundings * run.largest_set;
  double half[3];
  for (int i = 0; i < 3; ++i) {
    const double lo = run.run.lo[i];
    const double hi = run.run.hi[i];
    half[i] = std::min(0.5 * (hi - lo), most);
    const double centre = 0.5 * (now.lo[i] + now.hi[i]);
    camera->lookat[i] = std::clamp(centre, lo + half[i], hi - half[i]);
    half[i] *= 1 + kMargin;
  }
  // the camera's axes as mjv_updateCamera makes them from the angles
  const double azimuth = camera->azimuth * mjPI / 180;
  const double elevation = camera->elevation * mjPI / 180;
  const double forward[3] = {std::cos(elevation) * std::cos(azimuth),
                             std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
  const double up[3] = {-std::sin(elevation) * std::cos(azimuth),
                        -std::sin(elevation) * std::sin(azimuth), std::cos(elevation)};
  double right[3];
  mju_cross(right, forward, up);
  const double tan_y = std::tan(0.5 * m->vis.global.fovy * mjPI / 180);
  const double tan_x = aspect * tan_y;
  // the part of the frame below the overlay: (1 - top) of the height
  const double tan_free = (1 - top) * tan_y;
  // the nearest distance that keeps each corner of the view box inside the
  // frustum: its offset across the view within its depth times the tangent
  double distance = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const double c[3] = {corner & 1 ? half[0] : -half[0], corner & 2 ? half[1] : -half[1],
                         corner & 4 ? half[2] : -half[2]};
    const double along = mju_dot3(c, forward);
    distance = std::max({distance, std::abs(mju_dot3(c, right)) / tan_x - along,
                         std::abs(mju_dot3(c, up)) / tan_free - along});
  }
  camera->distance = distance;
  // the view box's centre to the free part's: the camera moved up across
  // the view, which keeps every depth
  mju_addToScl3(camera->lookat, up, top * tan_y * distance);
}

}  // namespace contactlaws::render
