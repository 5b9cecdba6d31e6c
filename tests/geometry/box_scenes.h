// Copyright contactlaws authors.
//
// Boxes placed in known contact, for the geometry tests (box_box_test,
// polytope_test): rotations, a landing body's attitude, a box's lowest
// point, a box put on another with a given overlap.

#ifndef CONTACTLAWS_TESTS_GEOMETRY_BOX_SCENES_H_
#define CONTACTLAWS_TESTS_GEOMETRY_BOX_SCENES_H_

#include <array>
#include <cmath>

#include "geometry/box_box.h"
#include "geometry/patch.h"

namespace contactlaws {
namespace box_scenes {

using Matrix = std::array<double, 9>;  // row-major

inline constexpr double kPi = 3.14159265358979323846;

using geometry::Add;
using geometry::Dot;
using geometry::Norm;
using geometry::Scale;
using geometry::Sub;

inline Vector3 Apply(const Matrix& m, const Vector3& v) {
  return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
          m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}
inline Vector3 ApplyTransposed(const Matrix& m, const Vector3& v) {
  return {m[0] * v[0] + m[3] * v[1] + m[6] * v[2], m[1] * v[0] + m[4] * v[1] + m[7] * v[2],
          m[2] * v[0] + m[5] * v[1] + m[8] * v[2]};
}
inline Matrix Multiply(const Matrix& a, const Matrix& b) {
  Matrix c{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
    }
  }
  return c;
}

// Rotation by degrees about axis (Rodrigues).
inline Matrix Rotation(Vector3 axis, double degrees) {
  axis = Scale(axis, 1 / Norm(axis));
  const double t = degrees * kPi / 180, c = std::cos(t), s = std::sin(t), k = 1 - c;
  const double x = axis[0], y = axis[1], z = axis[2];
  return {c + x * x * k,     x * y * k - z * s, x * z * k + y * s,
          y * x * k + z * s, c + y * y * k,     y * z * k - x * s,
          z * x * k - y * s, z * y * k + x * s, c + z * z * k};
}
inline const Matrix kIdentity = {1, 0, 0, 0, 1, 0, 0, 0, 1};

// The box's lowest point (its support along -z), world frame; a face or an
// edge gives its centre.
inline Vector3 Lowest(const OrientedBox& box) {
  const Vector3 down = ApplyTransposed(box.rotation, {0, 0, -1});
  Vector3 local{};
  for (int i = 0; i < 3; ++i) {
    local[i] = std::fabs(down[i]) < 1e-12 ? 0.0 : std::copysign(box.half[i], down[i]);
  }
  return Add(box.centre, Apply(box.rotation, local));
}

// A landing body's attitude: turned by yaw degrees about z, then tilted by
// tilt rad about the horizontal axis at heading rad from x.
inline Matrix LandingAttitude(double yaw, double tilt, double heading) {
  return Multiply(Rotation({std::cos(heading), std::sin(heading), 0}, tilt * 180 / kPi),
                  Rotation({0, 0, 1}, yaw));
}

// Box b above a: b's lowest point `overlap` below a's top face, at (x, y).
inline OrientedBox Above(const OrientedBox& a, const Matrix& rotation, const Vector3& half,
                  double overlap, double x = 0, double y = 0) {
  OrientedBox b{{0, 0, 0}, rotation, half};
  const Vector3 low = Lowest(b);
  const double top = a.centre[2] + a.half[2];
  b.centre = Sub({x, y, top - overlap}, low);
  return b;
}

}  // namespace box_scenes
}  // namespace contactlaws

#endif  // CONTACTLAWS_TESTS_GEOMETRY_BOX_SCENES_H_
