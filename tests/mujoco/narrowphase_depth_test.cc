// Copyright contactlaws authors.
//
// How far MuJoCo 2.2.2's narrowphase can be trusted, per pair of geom types.
//
// For every pair that mjCOLLISIONFUNC collides, two geoms are placed with a
// known overlap and the collision function is called directly. The oracle is
// built by construction: the top geom's lowest point (its support point along
// -z) is put right above the bottom geom's highest point (support along +z),
// `overlap` below it. The penetration depth is then exactly `overlap` along
// +z, as long as the overlap is small against the curvature radii and the
// extents of both geoms (here overlap <= 1e-2 of a 0.1 m size, radii >= 0.05 m).
//
// Each returned contact is also checked on its own: the vertical chord through
// its position crosses the bottom geom's upper surface and the top geom's lower
// surface (closed-form line/geom intersections); the local overlap is the gap
// between them and the exact contact position is the chord's midpoint.
//
// The tests assert the accuracy class measured for each pair type, with the
// faults found asserted as present (BoxBoxReturnsHalfTheOverlap, ...): they
// fail the day MuJoCo changes. NarrowphaseSurvey.PrintsTable prints the
// per-pair summary; NARROWPHASE_SURVEY=full prints every configuration.
//
// Links only MuJoCo and GoogleTest: build/tests/narrowphase_depth_test.

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

namespace {

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

Vec3 Add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 Sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 Scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double Dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double Norm(const Vec3& a) { return std::sqrt(Dot(a, a)); }

Vec3 MulMatVec(const Mat3& m, const Vec3& v) {
  return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
          m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}
Vec3 MulMatTVec(const Mat3& m, const Vec3& v) {
  return {m[0] * v[0] + m[3] * v[1] + m[6] * v[2], m[1] * v[0] + m[4] * v[1] + m[7] * v[2],
          m[2] * v[0] + m[5] * v[1] + m[8] * v[2]};
}

Quat AxisAngle(Vec3 axis, double degrees) {
  axis = Scale(axis, 1 / Norm(axis));
  const double h = 0.5 * degrees * kPi / 180;
  return {std::cos(h), std::sin(h) * axis[0], std::sin(h) * axis[1], std::sin(h) * axis[2]};
}

// a then b: the rotation b * a (b applied in the world frame after a).
Quat Then(const Quat& a, const Quat& b) {
  return {b[0] * a[0] - b[1] * a[1] - b[2] * a[2] - b[3] * a[3],
          b[0] * a[1] + b[1] * a[0] + b[2] * a[3] - b[3] * a[2],
          b[0] * a[2] - b[1] * a[3] + b[2] * a[0] + b[3] * a[1],
          b[0] * a[3] + b[1] * a[2] - b[2] * a[1] + b[3] * a[0]};
}

Mat3 QuatToMat(const Quat& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

double SignOrZero(double x) { return std::fabs(x) < kSupportZero ? 0.0 : (x > 0 ? 1.0 : -1.0); }

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
Vec3 Support(const Shape& s, const Vec3& dir) {
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
double EllipsoidDistance(const Vec3& a, const Vec3& p) {
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
double BoxDistance(const Vec3& h, const Vec3& p) {
  const Vec3 q = {std::fabs(p[0]) - h[0], std::fabs(p[1]) - h[1], std::fabs(p[2]) - h[2]};
  const Vec3 out = {std::max(q[0], 0.0), std::max(q[1], 0.0), std::max(q[2], 0.0)};
  return Norm(out) + std::min(std::max({q[0], q[1], q[2]}), 0.0);
}

// Signed distance from world point p to the geom (negative inside).
double SignedDistance(const Shape& s, const Vec3& p) {
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
Interval Intersect(Interval a, Interval b) { return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)}; }
Interval Hull(Interval a, Interval b) {
  if (a.Empty()) return b;
  if (b.Empty()) return a;
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}
const Interval kNothing{kInf, -kInf};

// lo <= o + t d <= hi.
Interval Range(double o, double d, double lo, double hi) {
  if (std::fabs(d) < 1e-300) return lo <= o && o <= hi ? Interval{} : kNothing;
  const double t1 = (lo - o) / d, t2 = (hi - o) / d;
  return {std::min(t1, t2), std::max(t1, t2)};
}

// Roots of sum_i mask_i (o_i + t d_i)^2 <= 1.
Interval UnitQuadric(const Vec3& o, const Vec3& d, const Vec3& mask) {
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

Interval SphereChord(const Vec3& o, const Vec3& d, double r) {
  return UnitQuadric(Scale(o, 1 / r), Scale(d, 1 / r), {1, 1, 1});
}

// Where the line p + t*dir (|dir| = 1) crosses the geom, in closed form.
Interval LineChord(const Shape& s, const Vec3& p, const Vec3& dir) {
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
double WitnessMiss(const Shape& s, const Vec3& w, const Vec3& n, bool upper) {
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

const char* TypeName(int type) {
  static const char* const kNames[] = {"plane", "hfield", "sphere", "capsule",
                                       "ellipsoid", "cylinder", "box", "mesh"};
  return kNames[type];
}

// The geom each type is surveyed with: every half-size between 0.05 and 0.1 m.
Vec3 GeomSize(int type) {
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
Quat Rest(int type) {
  return type == mjGEOM_CAPSULE ? AxisAngle({0, 1, 0}, 90) : Quat{1, 0, 0, 0};
}

bool IsGround(int type) { return type == mjGEOM_PLANE || type == mjGEOM_HFIELD; }
bool HasFlatFace(int type) {
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
std::vector<Config> ConfigsFor(int bottom, int top) {
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

//---------------------------------- MuJoCo side ---------------------------------------------------

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
struct VfsDeleter {
  void operator()(mjVFS* v) const {
    mj_deleteVFS(v);
    delete v;
  }
};
using UniqueModel = std::unique_ptr<mjModel, ModelDeleter>;
using UniqueData = std::unique_ptr<mjData, DataDeleter>;

// Loads an MJCF string through MuJoCo's virtual file system.
UniqueModel LoadXml(const std::string& xml, const std::string& name) {
  // mjVFS holds mjMAXVFS names and pointers: too large for the stack
  std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), name.c_str(), static_cast<int>(xml.size())) != 0) {
    ADD_FAILURE() << name << ": could not make a VFS file";
    return nullptr;
  }
  const int index = mj_findFileVFS(vfs.get(), name.c_str());
  std::memcpy(vfs->filedata[index], xml.data(), xml.size());
  char error[1000] = "";
  UniqueModel m(mj_loadXML(name.c_str(), vfs.get(), error, sizeof(error)));
  if (!m) ADD_FAILURE() << name << ": " << error;
  return m;
}

std::string GeomXml(int type) {
  const Vec3 s = GeomSize(type);
  char buf[200];
  switch (type) {
    case mjGEOM_PLANE: return R"(<geom type="plane" size="0 0 1"/>)";
    case mjGEOM_HFIELD: return R"(<geom type="hfield" hfield="flat"/>)";
    case mjGEOM_MESH: return R"(<geom type="mesh" mesh="boxmesh"/>)";
    default:
      std::snprintf(buf, sizeof(buf), R"(<geom type="%s" size="%.17g %.17g %.17g"/>)",
                    TypeName(type), s[0], s[1], s[2]);
      return buf;
  }
}

// Two geoms: geom 0 (bottom) on the world or a free body, geom 1 (top) on a
// free body. The mesh is the box of GeomSize(mjGEOM_MESH), given by vertices.
std::string PairXml(int bottom, int top) {
  const Vec3 b = GeomSize(mjGEOM_MESH);
  const Vec3 h = GeomSize(mjGEOM_HFIELD);
  char assets[1200];
  std::snprintf(assets, sizeof(assets),
                R"(<asset>
    <hfield name="flat" nrow="11" ncol="11" size="%g %g 0.1 %g"/>
    <mesh name="boxmesh" vertex="-%g -%g -%g  %g -%g -%g  -%g %g -%g  %g %g -%g
                                  -%g -%g %g  %g -%g %g  -%g %g %g  %g %g %g"/>
  </asset>)",
                h[0], h[1], h[2], b[0], b[1], b[2], b[0], b[1], b[2], b[0], b[1], b[2], b[0],
                b[1], b[2], b[0], b[1], b[2], b[0], b[1], b[2], b[0], b[1], b[2], b[0], b[1],
                b[2]);
  std::string world;
  if (IsGround(bottom)) {
    world = "    " + GeomXml(bottom) + "\n";
  } else {
    world = "    <body><freejoint/>" + GeomXml(bottom) + "</body>\n";
  }
  world += "    <body><freejoint/>" + GeomXml(top) + "</body>\n";
  return std::string("<mujoco>\n  ") + assets + "\n  <worldbody>\n" + world +
         "  </worldbody>\n</mujoco>\n";
}

//---------------------------------- one measurement -------------------------------------------------

// What MuJoCo returned for one configuration, against the exact answer.
struct Measurement {
  std::string pair, config;
  double fraction = 0;        // overlap / kSize
  double exact = 0;           // exact depth (m)
  double depth = 0;           // MuJoCo's deepest contact, -min(dist) (m); 0 if none
  int ncon = 0;
  double depth_error = 0;     // (depth - exact) / exact
  double witness = 0;         // worst distance of a contact's witness point from its surface / exact
  double normal_degrees = 0;  // worst angle between frame[0..2] and +z
};

// Places the pair, runs MuJoCo's collision function, compares.
class PairRig {
 public:
  PairRig(int bottom, int top)
      : bottom_(bottom), top_(top), name_(std::string(TypeName(bottom)) + "-" + TypeName(top)) {
    model_ = LoadXml(PairXml(bottom, top), name_ + ".xml");
    if (model_) data_.reset(mj_makeData(model_.get()));
  }
  bool ok() const { return data_ != nullptr; }
  const std::string& name() const { return name_; }
  mjModel* model() { return model_.get(); }
  void PrintContacts(bool on) { print_contacts_ = on; }
  const std::vector<mjContact>& LastContacts() const { return last_; }

  Measurement Measure(const Config& config, double fraction) {
    Measurement r;
    r.pair = name_;
    r.config = config.name;
    r.fraction = fraction;
    r.exact = fraction * kSize;

    // bottom geom: at the origin (a ground geom: the contact moved off the hfield grid lines)
    Shape lower{bottom_, GeomSize(bottom_)};
    const Quat qb = Then(Rest(bottom_), config.bottom);
    Vec3 high{0.037, 0.023, 0};
    if (!IsGround(bottom_)) {
      lower.rot = QuatToMat(qb);
      high = Support(lower, {0, 0, 1});
    }

    // top geom: its lowest point `exact` below the bottom geom's highest point
    Shape upper{top_, GeomSize(top_)};
    const Quat qt = Then(Rest(top_), config.top);
    upper.rot = QuatToMat(qt);
    const Vec3 low = Support(upper, {0, 0, -1});
    upper.pos = Sub(Add(high, {config.offset[0], config.offset[1], -r.exact}), low);

    // MuJoCo: the same poses through the free joints
    mjtNum* q = data_->qpos;
    if (!IsGround(bottom_)) {
      for (int i = 0; i < 3; ++i) q[i] = lower.pos[i];
      for (int i = 0; i < 4; ++i) q[3 + i] = qb[i];
      q += 7;
    }
    for (int i = 0; i < 3; ++i) q[i] = upper.pos[i];
    for (int i = 0; i < 4; ++i) q[3 + i] = qt[i];
    mj_kinematics(model_.get(), data_.get());
    mjContact con[mjMAXCONPAIR];
    std::memset(con, 0, sizeof(con));
    r.ncon = mjCOLLISIONFUNC[bottom_][top_](model_.get(), data_.get(), con, 0, 1, 0);

    // each contact's witness points pos -+ normal*dist/2 must lie on the surfaces
    for (int i = 0; i < r.ncon; ++i) {
      const mjContact& c = con[i];
      const Vec3 n = Scale({c.frame[0], c.frame[1], c.frame[2]},
                           1 / Norm({c.frame[0], c.frame[1], c.frame[2]}));
      const Vec3 pos = {c.pos[0], c.pos[1], c.pos[2]};
      r.depth = std::max(r.depth, -c.dist);
      r.normal_degrees = std::max(r.normal_degrees, std::acos(std::clamp(n[2], -1.0, 1.0)) * 180 / kPi);
      const double miss1 = WitnessMiss(lower, Sub(pos, Scale(n, 0.5 * c.dist)), n, false);
      const double miss2 = WitnessMiss(upper, Add(pos, Scale(n, 0.5 * c.dist)), n, true);
      r.witness = std::max({r.witness, std::fabs(miss1) / r.exact, std::fabs(miss2) / r.exact});
      if (print_contacts_) {
        std::printf("  %-19s %-8s %7.0e #%d pos %+.6f %+.6f %+.9f dist %+.4e n %+.3f %+.3f %+.3f"
                    " miss %+.2e %+.2e\n", r.pair.c_str(), r.config.c_str(), fraction, i,
                    pos[0], pos[1], pos[2], c.dist, n[0], n[1], n[2], miss1, miss2);
      }
    }
    last_.assign(con, con + r.ncon);
    r.depth_error = (r.depth - r.exact) / r.exact;
    return r;
  }

 private:
  int bottom_, top_;
  std::string name_;
  UniqueModel model_;
  UniqueData data_;
  bool print_contacts_ = false;
  std::vector<mjContact> last_;
};

// Every pair MuJoCo 2.2.2 collides: upper triangle of mjCOLLISIONFUNC.
std::vector<std::pair<int, int>> CollidedPairs() {
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < mjNGEOMTYPES; ++i) {
    for (int j = i; j < mjNGEOMTYPES; ++j) {
      if (mjCOLLISIONFUNC[i][j]) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

std::vector<Measurement> MeasureAll(int bottom, int top, bool print_contacts = false) {
  PairRig rig(bottom, top);
  rig.PrintContacts(print_contacts);
  std::vector<Measurement> rows;
  if (!rig.ok()) return rows;
  for (const Config& c : ConfigsFor(bottom, top)) {
    for (double f : kOverlapFractions) rows.push_back(rig.Measure(c, f));
  }
  return rows;
}

void PrintRow(const Measurement& r) {
  std::printf("%-19s %-8s %7.0e %10.3e %10.3e %+10.2e %3d %9.2e %7.2f\n", r.pair.c_str(),
              r.config.c_str(), r.fraction, r.exact, r.depth, r.depth_error, r.ncon, r.witness,
              r.normal_degrees);
}

void PrintHeader() {
  std::printf("%-19s %-8s %7s %10s %10s %10s %3s %9s %7s\n", "pair", "config", "ovl/size",
              "exact(m)", "mujoco(m)", "rel.err", "n", "witness", "n.deg");
}

//---------------------------------- fixture -------------------------------------------------------

// Fails the test on any MuJoCo warning.
class Narrowphase : public ::testing::Test {
 protected:
  void SetUp() override {
    previous_ = mju_user_warning;
    mju_user_warning = [](const char* msg) { ADD_FAILURE() << "MuJoCo warning: " << msg; };
  }
  void TearDown() override { mju_user_warning = previous_; }

 private:
  void (*previous_)(const char*) = nullptr;
};

using NarrowphaseSurvey = Narrowphase;

TEST_F(NarrowphaseSurvey, PrintsTable) {
  const char* env = std::getenv("NARROWPHASE_SURVEY");
  const bool contacts = env && std::string(env) == "contacts";
  const bool full = contacts || (env && std::string(env) == "full");
  PrintHeader();
  for (const auto& [b, t] : CollidedPairs()) {
    const std::vector<Measurement> rows = MeasureAll(b, t, contacts);
    ASSERT_FALSE(rows.empty());
    if (full) {
      for (const Measurement& r : rows) PrintRow(r);
      continue;
    }
    // summary: the row with the worst depth error
    const auto worst = std::max_element(rows.begin(), rows.end(), [](auto& x, auto& y) {
      return std::fabs(x.depth_error) < std::fabs(y.depth_error);
    });
    PrintRow(*worst);
  }
}


//---------------------------------- the accuracy class of each pair type ---------------------------

// Closed-form pairs: the error is round-off of positions near 0.1 m, seen
// against a 1e-8 m overlap and amplified by up to ~50 through a 1-degree tilt
// (measured worst 4.1e-8, plane-cylinder tilt1).
constexpr double kRoundOffRel = 1e-6;

// Mesh vertices are stored as float: each coordinate near 0.1 m is off by up
// to half a float ulp (3.7e-9 m), and a depth involves two of them.
constexpr double kFloatVertexAbs = 1e-8;

// A ratio asserted exactly (box-box's halving): only round-off around it.
constexpr double kRatioTol = 1e-6;

// MPR (libccd) stops when its portal moves by less than opt.mpr_tolerance
// (1e-6 m by default): below it the depth is not resolved at all.
constexpr double kMprTolerance = 1e-6;

// All the measurements of one pair type.
std::vector<Measurement> Rows(int bottom, int top) { return MeasureAll(bottom, top); }

// The measurement of one configuration.
Measurement Row(int bottom, int top, const std::string& config, double fraction) {
  for (const Measurement& r : MeasureAll(bottom, top)) {
    if (r.config == config && r.fraction == fraction) return r;
  }
  ADD_FAILURE() << TypeName(bottom) << "-" << TypeName(top) << ": no " << config;
  return {};
}

TEST_F(Narrowphase, ClosedFormPairsAreExactToRoundOff) {
  const std::pair<int, int> exact[] = {
      {mjGEOM_PLANE, mjGEOM_SPHERE},    {mjGEOM_PLANE, mjGEOM_CAPSULE},
      {mjGEOM_PLANE, mjGEOM_ELLIPSOID}, {mjGEOM_PLANE, mjGEOM_CYLINDER},
      {mjGEOM_PLANE, mjGEOM_BOX},       {mjGEOM_SPHERE, mjGEOM_SPHERE},
      {mjGEOM_SPHERE, mjGEOM_CAPSULE},  {mjGEOM_SPHERE, mjGEOM_BOX},
      {mjGEOM_CAPSULE, mjGEOM_CAPSULE}, {mjGEOM_CAPSULE, mjGEOM_BOX},
      {mjGEOM_HFIELD, mjGEOM_BOX}};  // hfield-box: MPR between polytopes lands on a face
  for (const auto& [b, t] : exact) {
    for (const Measurement& r : Rows(b, t)) {
      EXPECT_GE(r.ncon, 1) << r.pair << " " << r.config << " " << r.fraction;
      EXPECT_LT(std::fabs(r.depth_error), kRoundOffRel) << r.pair << " " << r.config << " "
                                                        << r.fraction;
    }
  }
}

TEST_F(Narrowphase, MeshDepthIsExactToFloatVertices) {
  // plane-mesh takes vertices; box-mesh and mesh-mesh go through MPR, which
  // lands exactly on polytope faces
  for (const auto& [b, t] : {std::pair{mjGEOM_PLANE, mjGEOM_MESH}, {mjGEOM_BOX, mjGEOM_MESH},
                             {mjGEOM_MESH, mjGEOM_MESH}}) {
    for (const Measurement& r : Rows(b, t)) {
      EXPECT_GE(r.ncon, 1) << r.pair << " " << r.config << " " << r.fraction;
      EXPECT_LT(std::fabs(r.depth - r.exact), kFloatVertexAbs) << r.pair << " " << r.config;
    }
  }
  // and the float error is visible: 0.05f - 0.05 = 7.45e-10 m on a 1e-8 m overlap
  const Measurement r = Row(mjGEOM_PLANE, mjGEOM_MESH, "face", 1e-7);
  EXPECT_NEAR(r.depth_error, 0.0745, 0.001);
}

TEST_F(Narrowphase, PlaneMeshReturnsThreeOfFourCorners) {
  // mjc_PlaneConvex stops at maxplanemesh = 3 contacts: a flat box mesh
  // rests on 3 corners, so the contact force has a torque about the centre
  EXPECT_EQ(Row(mjGEOM_PLANE, mjGEOM_MESH, "face", 1e-3).ncon, 3);
  EXPECT_EQ(Row(mjGEOM_PLANE, mjGEOM_BOX, "face", 1e-3).ncon, 4);
}

TEST_F(Narrowphase, BoxBoxReturnsHalfTheOverlap) {
  // the face path of mjc_BoxBox halves the point's depth (so that pos is
  // midway) and then reports the halved value as dist
  for (const char* config : {"face", "offset", "corner", "tilt1", "tilt5", "tilt20", "rot45z",
                             "cross90"}) {
    for (double f : kOverlapFractions) {
      const Measurement r = Row(mjGEOM_BOX, mjGEOM_BOX, config, f);
      EXPECT_NEAR(r.depth / r.exact, 0.5, kRatioTol) << config << " " << f;
    }
  }
}

TEST_F(Narrowphase, BoxBoxEdgePathGivesTheFullOverlap) {
  // edge-edge contacts go through the other path, which reports full depths
  for (double f : kOverlapFractions) {
    EXPECT_LT(std::fabs(Row(mjGEOM_BOX, mjGEOM_BOX, "crossed", f).depth_error), kRoundOffRel);
  }
  // a box on its edge switches between the two paths with the overlap
  EXPECT_LT(std::fabs(Row(mjGEOM_BOX, mjGEOM_BOX, "edge", 1e-5).depth_error), kRoundOffRel);
  EXPECT_NEAR(Row(mjGEOM_BOX, mjGEOM_BOX, "edge", 1e-3).depth_error, -0.5, kRatioTol);
}

// The contacts of one configuration, for the tests that look at positions.
std::vector<mjContact> Contacts(int bottom, int top, const Config& config, double fraction) {
  PairRig rig(bottom, top);
  rig.Measure(config, fraction);
  return rig.LastContacts();
}

const Config& FindConfig(int bottom, int top, const std::string& name) {
  static std::vector<Config> all;
  all = ConfigsFor(bottom, top);
  for (const Config& c : all) {
    if (c.name == name) return c;
  }
  ADD_FAILURE() << "no configuration " << name;
  return all.front();
}

TEST_F(Narrowphase, BoxBoxDuplicatesCornersOfAlignedFaces) {
  // two equal aligned boxes: 9 contacts at 4 distinct corners
  const std::vector<mjContact> con =
      Contacts(mjGEOM_BOX, mjGEOM_BOX, FindConfig(mjGEOM_BOX, mjGEOM_BOX, "face"), 1e-3);
  std::vector<Vec3> distinct;
  for (const mjContact& c : con) {
    const Vec3 p = {c.pos[0], c.pos[1], c.pos[2]};
    if (std::none_of(distinct.begin(), distinct.end(),
                     [&](const Vec3& q) { return Norm(Sub(p, q)) < 1e-12; })) {
      distinct.push_back(p);
    }
  }
  EXPECT_EQ(con.size(), 9u);
  EXPECT_EQ(distinct.size(), 4u);
}

TEST_F(Narrowphase, BoxBoxEmitsAContactOutsideTheFace) {
  // the top box turned 45 degrees about the vertical: its nearest corner is
  // always emitted, even where it hangs beyond the bottom box's face
  const std::vector<mjContact> con =
      Contacts(mjGEOM_BOX, mjGEOM_BOX, FindConfig(mjGEOM_BOX, mjGEOM_BOX, "rot45z"), 1e-3);
  const Vec3 half = GeomSize(mjGEOM_BOX);
  double beyond = 0;
  for (const mjContact& c : con) {
    beyond = std::max({beyond, std::fabs(c.pos[0]) - half[0], std::fabs(c.pos[1]) - half[1]});
  }
  EXPECT_GT(beyond, 0.04);  // 4.7 cm beyond the face, reported as penetrating
}

TEST_F(Narrowphase, MprMissesOverlapsBelowItsTolerance) {
  // smooth pairs through libccd: an overlap of 1e-8 m (below mpr_tolerance)
  // returns no contact at all, 1e-6 m comes back tens of percent short
  const std::pair<int, int> mpr[] = {
      {mjGEOM_SPHERE, mjGEOM_ELLIPSOID},    {mjGEOM_SPHERE, mjGEOM_CYLINDER},
      {mjGEOM_SPHERE, mjGEOM_MESH},         {mjGEOM_CAPSULE, mjGEOM_ELLIPSOID},
      {mjGEOM_CAPSULE, mjGEOM_CYLINDER},    {mjGEOM_CAPSULE, mjGEOM_MESH},
      {mjGEOM_ELLIPSOID, mjGEOM_ELLIPSOID}, {mjGEOM_ELLIPSOID, mjGEOM_CYLINDER},
      {mjGEOM_ELLIPSOID, mjGEOM_BOX},       {mjGEOM_ELLIPSOID, mjGEOM_MESH},
      {mjGEOM_HFIELD, mjGEOM_SPHERE},       {mjGEOM_HFIELD, mjGEOM_ELLIPSOID}};
  PairRig defaults(mjGEOM_SPHERE, mjGEOM_ELLIPSOID);
  ASSERT_TRUE(defaults.ok());
  ASSERT_EQ(defaults.model()->opt.mpr_tolerance, kMprTolerance);
  for (const auto& [b, t] : mpr) {
    int missed = 0;
    double worst_micron = 0;
    for (const Measurement& r : Rows(b, t)) {
      if (r.fraction == 1e-7 && r.ncon == 0) ++missed;
      if (r.fraction == 1e-5) worst_micron = std::max(worst_micron, std::fabs(r.depth_error));
    }
    const std::string pair = std::string(TypeName(b)) + "-" + TypeName(t);
    EXPECT_GT(missed, 0) << pair;
    EXPECT_GT(worst_micron, 0.05) << pair;
  }
}

TEST_F(Narrowphase, MprOverestimatesWhenTheCentresAreOffTheNormal) {
  // MPR searches along the line between the centres: a tilted box whose
  // corner touches an ellipsoid's top is 46% too deep at a 1 mm overlap
  EXPECT_GT(Row(mjGEOM_ELLIPSOID, mjGEOM_BOX, "tilt5", 1e-2).depth_error, 0.4);
  EXPECT_GT(Row(mjGEOM_SPHERE, mjGEOM_CYLINDER, "tilt1", 1e-2).depth_error, 0.15);
}

}  // namespace
