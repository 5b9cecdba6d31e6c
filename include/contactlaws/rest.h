// Copyright contactlaws authors.
//
// Where measured bodies come to rest, and how far a replay's last state is
// from the measured one (docs/identification.md, "Resting poses"):
//
//   at rest      a trajectory whose body moves slower than RestRule::speed
//                between each of its last RestRule::samples samples;
//   plane height a body at rest on a plane: its resting height (the mean
//                over the samples found at rest) less its support distance
//                (the depth of its lowest point below its origin on the
//                face it rests on: a cube's half side), one estimate per
//                trajectory at rest;
//   end gaps     the last sample's simulated position less the measured
//                (height and horizontal distance), the rotation between the
//                two orientations, and the tilt: the angle between the
//                vertical seen from the simulated body and from the measured
//                one, which a turn about the vertical leaves at 0. A tilt
//                above 45 degrees puts another side of a cube up: "another
//                face".

#ifndef CONTACTLAWS_REST_H_
#define CONTACTLAWS_REST_H_

#include <cstdint>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/measured.h"
#include "contactlaws/replay.h"
#include "contactlaws/statistics.h"

namespace contactlaws {

// The cube tosses' tracking (148 Hz) moves a resting cube by ~0.008 m/s
// from sample to sample (the median over the last 5 intervals of the
// training tosses); 0.02 m/s is 2.5 times that, 0.14 mm per sample.
struct RestRule {
  double speed = 0.02;  // m/s
  int samples = 5;      // the last intervals checked
};

// A body of the data: its name and its x and qw columns (qw -1 when its
// orientation is not measured).
struct MeasuredBodyColumns {
  std::string name;
  int x = -1, qw = -1;
};
// Every NAME with NAME.x, NAME.y and NAME.z columns, in the data's order.
std::vector<MeasuredBodyColumns> MeasuredBodies(const MeasuredData& data);

// Whether body ends trajectory t at rest under rule (a trajectory shorter
// than rule.samples + 1 samples does not).
bool EndsAtRest(const MeasuredData& data, const MeasuredTrajectory& t,
                const MeasuredBodyColumns& body, const RestRule& rule);

// How far body's lowest point lies below its origin along the world's z,
// at orientation q (w, x, y, z): the largest support distance of its
// colliding geoms (box, sphere, capsule, cylinder, ellipsoid). resting: each
// geom on its face, end or side nearest to facing down (the world's -z
// snapped to the geom's nearest axis), as a body at rest lies; a tracked
// orientation's error of a degree, which the support function's corner
// turns into a bias (+0.7 mm on the tosses' resting cubes), then drops out.
// Throws Error naming the body for another geom type or a body without
// colliding geoms.
double SupportDistance(const mjModel* m, int body, const double q[4], bool resting = false);

// At least this many trajectories at rest for a plane's estimate: fewer
// leave its bootstrap interval resampling one or two values.
inline constexpr int kMinimumAtRest = 5;

struct PlaneEstimate {
  int trajectories = 0;  // of every measured body
  int at_rest = 0;
  Summary height;  // the plane's height, m: median and its interval, per trajectory at rest
  Distribution support;  // the support distances, m
};
// The height of the plane the data's bodies rest on (bodies of m named as
// in the data; orientations the model's own when not measured). Throws
// Error, in one line naming the data, the rule and how many came to rest,
// when fewer than kMinimumAtRest did.
PlaneEstimate EstimatePlaneHeight(const mjModel* m, const MeasuredData& data,
                                  const RestRule& rule, uint64_t seed);

// One body's gaps at trajectory i's last sample.
struct EndGap {
  bool at_rest = false;       // the measured trajectory ends at rest
  double measured_z = 0;      // m
  double simulated_z = 0;     // m
  double horizontal = 0;      // m
  double angle = 0;           // rad, the whole rotation (0 unmeasured)
  double tilt = 0;            // rad, the vertical's (0 unmeasured)
};
// Per trajectory, per body of MeasuredBodies (its order): replayed[i].last
// against data's last sample.
std::vector<std::vector<EndGap>> EndGaps(const MeasuredData& data,
                                         const std::vector<ReplayedTrajectory>& replayed,
                                         const RestRule& rule);

// A cube's neighbouring faces are 90 degrees apart: half that.
inline constexpr double kAnotherFaceTilt = 0.7853981633974483;  // pi / 4, rad

}  // namespace contactlaws

#endif  // CONTACTLAWS_REST_H_
