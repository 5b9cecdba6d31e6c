// Copyright contactlaws authors.
//
// The oracle of the narrowphase tests: geoms in closed form (support points,
// signed distances, chords along a line), the pairs of geom types and the
// configurations they are placed in. No MuJoCo call.

#ifndef CONTACTLAWS_TESTS_MUJOCO_NARROWPHASE_ORACLE_H_
#define CONTACTLAWS_TESTS_MUJOCO_NARROWPHASE_ORACLE_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

namespace narrowphase_test {

using Vec3 = std::array<double, 3>;
using Quat = std::array<double, 4>;  // w, x, y, z (MuJoCo's order)
using Mat3 = std::array<double, 9>;  // row-major (MuJoCo's order)

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Size every overlap is a fraction of: the largest half-size of the geoms.
constexpr double kSize = 0.1;

// Overlaps surveyed, as fractions of kSize: from 10 nm to 1 mm.
constexpr std::array<double, 4> kOverlapFractions = {1e-7, 1e-5, 1e-3, 1e-2};

// Support points: a direction component below this (in the geom's frame) is
// taken as exactly zero, so a face or an edge yields its centre.
constexpr double kSupportZero = 1e-12;

//---------------------------------- small linear algebra --------------------------------------------

inline Vec3 Add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 Sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 Scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double Dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double Norm(const Vec3& a) { return std::sqrt(Dot(a, a)); }

inline Vec3 MulMatVec(const Mat3& m, const Vec3& v) {
  return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
          m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}
inline Vec3 MulMatTVec(const Mat3& m, const Vec3& v) {
  return {m[0] * v[0] + m[3] * v[1] + m[6] * v[2], m[1] * v[0] + m[4] * v[1] + m[7] * v[2],
          m[2] * v[0] + m[5] * v[1] + m[8] * v[2]};
}

inline Quat AxisAngle(Vec3 axis, double degrees) {
  axis = Scale(axis, 1 / Norm(axis));
  const double h = 0.5 * degrees * kPi / 180;
  return {std::cos(h), std::sin(h) * axis[0], std::sin(h) * axis[1], std::sin(h) * axis[2]};
}

// a then b: the rotation b * a (b applied in the world frame after a).
inline Quat Then(const Quat& a, const Quat& b) {
  return {b[0] * a[0] - b[1] * a[1] - b[2] * a[2] - b[3] * a[3],
          b[0] * a[1] + b[1] * a[0] + b[2] * a[3] - b[3] * a[2],
          b[0] * a[2] - b[1] * a[3] + b[2] * a[0] + b[3] * a[1],
          b[0] * a[3] + b[1] * a[2] - b[2] * a[1] + b[3] * a[0]};
}

inline Mat3 QuatToMat(const Quat& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

inline double SignOrZero(double x) { return std::fabs(x) < kSupportZero ? 0.0 : (x > 0 ? 1.0 : -1.0); }

//---------------------------------- the oracle: geoms in closed form --------------------------------

// A geom as the oracle sees it: built from the pose the test asked for, not
// from MuJoCo's output. A mesh is the box its vertices describe; an hfield is
// flat (all heights zero), so it is the slab -base <= z <= 0.
struct Shape {
  int type = mjGEOM_PLANE;
  Vec3 size{};  // MuJoCo's geom size; for hfield: (x half, y half, base)
  Vec3 pos{};
  Mat3 rot{1, 0, 0, 0, 1, 0, 0, 0, 1};
};

// Farthest point of s along dir (world frame). Not used for planes/hfields.
inline Vec3 Support(const Shape& s, const Vec3& dir) {
  const Vec3 d = MulMatTVec(s.rot, dir);
  Vec3 local{};
  switch (s.type) {
    case mjGEOM_SPHERE:
      local = Scale(d, s.size[0] / Norm(d));
      break;
    case mjGEOM_CAPSULE:
      local = Scale(d, s.size[0] / Norm(d));
      local[2] += SignOrZero(d[2]) * s.size[1];
      break;
    case mjGEOM_ELLIPSOID: {
      const Vec3 a2d = {s.size[0] * s.size[0] * d[0], s.size[1] * s.size[1] * d[1],
                        s.size[2] * s.size[2] * d[2]};
      local = Scale(a2d, 1 / std::sqrt(Dot(a2d, d)));
      break;
    }
    case mjGEOM_CYLINDER: {
      const double radial = std::hypot(d[0], d[1]);
      if (radial > kSupportZero) local = {d[0] / radial * s.size[0], d[1] / radial * s.size[0], 0};
      local[2] = SignOrZero(d[2]) * s.size[1];
      break;
    }
    case mjGEOM_BOX:
    case mjGEOM_MESH:
      for (int i = 0; i < 3; ++i) local[i] = SignOrZero(d[i]) * s.size[i];
      break;
    default:
      ADD_FAILURE() << "no support function for geom type " << s.type;
  }
  return Add(s.pos, MulMatVec(s.rot, local));
}

// Signed distance from point p to the ellipsoid with semi-axes a (local
// frame): the closest point is x_i = a_i^2 y_i / (t + a_i^2) for the root t of
// sum (a_i y_i / (t + a_i^2))^2 = 1, found by bisection (Eberly's method).
inline double EllipsoidDistance(const Vec3& a, const Vec3& p) {
  const Vec3 y = {std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])};
  const auto excess = [&](double t) {
    double sum = -1;
    for (int i = 0; i < 3; ++i) {
      const double r = a[i] * y[i] / (t + a[i] * a[i]);
      sum += r * r;
    }
    return sum;
  };
  const double amin = std::min({a[0], a[1], a[2]});
  double lo = -amin * amin, hi = Norm(y) * std::max({a[0], a[1], a[2]});
  for (int k = 0; k < 200 && hi - lo > 0; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (excess(mid) > 0 ? lo : hi) = mid;
  }
  const double t = 0.5 * (lo + hi);
  Vec3 x;
  for (int i = 0; i < 3; ++i) x[i] = a[i] * a[i] * y[i] / (t + a[i] * a[i]);
  const double d = Norm(Sub(x, y));
  return t < 0 ? -d : d;
}

// Signed distance of a box with half-sizes h, centred at the origin.
inline double BoxDistance(const Vec3& h, const Vec3& p) {
  const Vec3 q = {std::fabs(p[0]) - h[0], std::fabs(p[1]) - h[1], std::fabs(p[2]) - h[2]};
  const Vec3 out = {std::max(q[0], 0.0), std::max(q[1], 0.0), std::max(q[2], 0.0)};
  return Norm(out) + std::min(std::max({q[0], q[1], q[2]}), 0.0);
}

// Signed distance from world point p to the geom (negative inside).
inline double SignedDistance(const Shape& s, const Vec3& p) {
  const Vec3 o = MulMatTVec(s.rot, Sub(p, s.pos));
  switch (s.type) {
    case mjGEOM_PLANE:
    case mjGEOM_HFIELD:  // flat hfield: its top is z = 0; contacts never reach its base
      return o[2];
    case mjGEOM_SPHERE:
      return Norm(o) - s.size[0];
    case mjGEOM_CAPSULE: {
      const double z = std::clamp(o[2], -s.size[1], s.size[1]);
      return Norm({o[0], o[1], o[2] - z}) - s.size[0];
    }
    case mjGEOM_ELLIPSOID:
      return EllipsoidDistance(s.size, o);
    case mjGEOM_CYLINDER: {
      const double qr = std::hypot(o[0], o[1]) - s.size[0];
      const double qz = std::fabs(o[2]) - s.size[1];
      return std::hypot(std::max(qr, 0.0), std::max(qz, 0.0)) + std::min(std::max(qr, qz), 0.0);
    }
    case mjGEOM_BOX:
    case mjGEOM_MESH:
      return BoxDistance(s.size, o);
  }
  ADD_FAILURE() << "no signed distance for geom type " << s.type;
  return 0;
}

// An interval of a line's parameter t; empty when lo > hi.
struct Interval {
  double lo = -kInf, hi = kInf;
  bool Empty() const { return lo > hi; }
};
inline Interval Intersect(Interval a, Interval b) { return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)}; }
inline Interval Hull(Interval a, Interval b) {
  if (a.Empty()) return b;
  if (b.Empty()) return a;
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}
const Interval kNothing{kInf, -kInf};

// lo <= o + t d <= hi.
inline Interval Range(double o, double d, double lo, double hi) {
  if (std::fabs(d) < 1e-300) return lo <= o && o <= hi ? Interval{} : kNothing;
  const double t1 = (lo - o) / d, t2 = (hi - o) / d;
  return {std::min(t1, t2), std::max(t1, t2)};
}

// Roots of sum_i mask_i (o_i + t d_i)^2 <= 1.
inline Interval UnitQuadric(const Vec3& o, const Vec3& d, const Vec3& mask) {
  double a = 0, b = 0, c = -1;
  for (int i = 0; i < 3; ++i) {
    a += mask[i] * d[i] * d[i];
    b += 2 * mask[i] * o[i] * d[i];
    c += mask[i] * o[i] * o[i];
  }
  if (a < 1e-300) return c <= 0 ? Interval{} : kNothing;
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return kNothing;
  const double r = std::sqrt(disc);
  return {(-b - r) / (2 * a), (-b + r) / (2 * a)};
}

inline Interval SphereChord(const Vec3& o, const Vec3& d, double r) {
  return UnitQuadric(Scale(o, 1 / r), Scale(d, 1 / r), {1, 1, 1});
}

// Where the line p + t*dir (|dir| = 1) crosses the geom, in closed form.
inline Interval LineChord(const Shape& s, const Vec3& p, const Vec3& dir) {
  const Vec3 o = MulMatTVec(s.rot, Sub(p, s.pos));
  const Vec3 d = MulMatTVec(s.rot, dir);
  const Vec3 h = s.size;
  switch (s.type) {
    case mjGEOM_PLANE:
      return Range(o[2], d[2], -kInf, 0);
    case mjGEOM_HFIELD:  // flat: -base <= z <= 0 within the x/y extent
      return Intersect(Intersect(Range(o[0], d[0], -h[0], h[0]), Range(o[1], d[1], -h[1], h[1])),
                       Range(o[2], d[2], -h[2], 0));
    case mjGEOM_SPHERE:
      return SphereChord(o, d, h[0]);
    case mjGEOM_CAPSULE: {
      const Interval body = Intersect(UnitQuadric(Scale(o, 1 / h[0]), Scale(d, 1 / h[0]), {1, 1, 0}),
                                      Range(o[2], d[2], -h[1], h[1]));
      const Interval cap1 = SphereChord(Sub(o, {0, 0, h[1]}), d, h[0]);
      const Interval cap2 = SphereChord(Add(o, {0, 0, h[1]}), d, h[0]);
      return Hull(Hull(body.Empty() ? kNothing : body, cap1), cap2);
    }
    case mjGEOM_ELLIPSOID:
      return UnitQuadric({o[0] / h[0], o[1] / h[1], o[2] / h[2]},
                         {d[0] / h[0], d[1] / h[1], d[2] / h[2]}, {1, 1, 1});
    case mjGEOM_CYLINDER:
      return Intersect(UnitQuadric(Scale(o, 1 / h[0]), Scale(d, 1 / h[0]), {1, 1, 0}),
                       Range(o[2], d[2], -h[1], h[1]));
    case mjGEOM_BOX:
    case mjGEOM_MESH: {
      Interval in;
      for (int i = 0; i < 3; ++i) in = Intersect(in, Range(o[i], d[i], -h[i], h[i]));
      return in;
    }
  }
  ADD_FAILURE() << "no chord for geom type " << s.type;
  return kNothing;
}

// Lateral step of the chord samples: a witness point on a corner of a steep
// face, displaced by round-off, can see the chord enter far up that face;
// one of the four samples this far aside sees the face the point is on.
constexpr double kChordStep = 1e-12;

// How far witness point w is from the surface of s it should lie on, along n:
// the exit of s (upper = false: s is below, w on its top) or its entry
// (upper = true). Falls back to the signed distance when no chord meets s.
inline double WitnessMiss(const Shape& s, const Vec3& w, const Vec3& n, bool upper) {
  Vec3 u = std::fabs(n[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  u = Sub(u, Scale(n, Dot(u, n)));
  u = Scale(u, 1 / Norm(u));
  const Vec3 v = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
  double best = kInf;
  const Vec3 steps[5] = {{0, 0, 0}, u, Scale(u, -1), v, Scale(v, -1)};
  for (const Vec3& step : steps) {
    const Interval c = LineChord(s, Add(w, Scale(step, kChordStep)), n);
    if (c.Empty()) continue;
    const double miss = upper ? c.lo : c.hi;
    if (std::fabs(miss) < std::fabs(best)) best = miss;
  }
  return std::isfinite(best) ? best : SignedDistance(s, w);
}

//---------------------------------- the pairs and their configurations ------------------------------

inline const char* TypeName(int type) {
  static const char* const kNames[] = {"plane", "hfield", "sphere", "capsule",
                                       "ellipsoid", "cylinder", "box", "mesh"};
  return kNames[type];
}

// The geom each type is surveyed with: every half-size between 0.05 and 0.1 m.
inline Vec3 GeomSize(int type) {
  switch (type) {
    case mjGEOM_PLANE: return {0, 0, 1};
    case mjGEOM_HFIELD: return {1, 1, 0.1};  // x, y half-extents and base
    case mjGEOM_SPHERE: return {0.1, 0, 0};
    case mjGEOM_CAPSULE: return {0.05, 0.1, 0};
    case mjGEOM_ELLIPSOID: return {0.1, 0.08, 0.05};
    case mjGEOM_CYLINDER: return {0.1, 0.05, 0};
    default: return {0.1, 0.08, 0.05};  // box, and the mesh box
  }
}

// Resting orientation: a capsule lies along x; everything else as authored
// (cylinder standing on its disk, ellipsoid with its short axis vertical).
inline Quat Rest(int type) {
  return type == mjGEOM_CAPSULE ? AxisAngle({0, 1, 0}, 90) : Quat{1, 0, 0, 0};
}

inline bool IsGround(int type) { return type == mjGEOM_PLANE || type == mjGEOM_HFIELD; }
inline bool HasFlatFace(int type) {
  return type == mjGEOM_BOX || type == mjGEOM_MESH || type == mjGEOM_CYLINDER;
}

// A placement of the two geoms, before the overlap is applied.
struct Config {
  std::string name;
  Quat bottom{1, 0, 0, 0};  // applied after Rest(bottom type)
  Quat top{1, 0, 0, 0};     // applied after Rest(top type)
  Vec3 offset{};            // lateral shift of the top geom's lowest point
};

// The configurations that make sense for a pair (bottom type <= top type).
inline std::vector<Config> ConfigsFor(int bottom, int top) {
  const Quat none{1, 0, 0, 0};
  // tilts about a generic horizontal axis, so one box corner is lowest
  const Vec3 tilt_axis = {std::cos(kPi / 6), std::sin(kPi / 6), 0};
  const Quat corner = Then(AxisAngle({1, 0, 0}, 45), AxisAngle({0, 1, 0}, 35.26438968));
  std::vector<Config> c = {{"face", none, none, {}}};
  if (top == mjGEOM_SPHERE) return c;  // a sphere has no orientation
  if (HasFlatFace(bottom) && HasFlatFace(top)) c.push_back({"offset", none, none, {0.03, 0.02, 0}});
  c.push_back({"edge", none, AxisAngle({1, 0, 0}, 45), {}});
  c.push_back({"corner", none, corner, {}});
  for (double deg : {1.0, 5.0, 20.0}) {
    c.push_back({"tilt" + std::to_string(static_cast<int>(deg)), none, AxisAngle(tilt_axis, deg), {}});
  }
  if (!IsGround(bottom) && bottom != mjGEOM_SPHERE) {
    c.push_back({"rot45z", none, AxisAngle({0, 0, 1}, 45), {}});
    c.push_back({"cross90", none, AxisAngle({0, 0, 1}, 90), {}});
    c.push_back({"crossed", AxisAngle({0, 1, 0}, 45), AxisAngle({1, 0, 0}, 45), {}});
  }
  return c;
}
}  // namespace narrowphase_test

#endif  // CONTACTLAWS_TESTS_MUJOCO_NARROWPHASE_ORACLE_H_
