// Copyright contactlaws authors.

#include "scene/pair_trust.h"

#include <algorithm>

#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include "geometry/polytope.h"

static_assert(contactlaws::kMaxPolytopeVertices == 64 && contactlaws::kMaxPolytopeTriangles == 124,
              "the box-mesh and mesh-mesh warnings name the polytope caps");

namespace contactlaws {
namespace {

// The pairs not trusted as MuJoCo gives them, with the survey's numbers
// (docs/geometry.md; NARROWPHASE_SURVEY=full build/tests/narrowphase_depth_test):
// the worst depth error at a 1e-6 m overlap and at 1e-4..1e-3 m.
struct Row {
  int type1, type2;  // type1 <= type2
  DepthTrust trust;
  const char* why;
};

constexpr const char* kMprRefused =
    "MuJoCo 2.2.2 gives its depth by MPR (libccd), {} (docs/geometry.md): the laws would act "
    "on a wrong depth; use other geom types, or leave the pair untagged";

const Row kRows[] = {
    {mjGEOM_BOX, mjGEOM_BOX, DepthTrust::kComputed, ""},
    // MPR between smooth shapes: refused (kRefusedErrorAt...)
    {mjGEOM_HFIELD, mjGEOM_ELLIPSOID, DepthTrust::kRefused, "66% short at 1e-6 m"},
    {mjGEOM_HFIELD, mjGEOM_MESH, DepthTrust::kRefused, "2.5% deep at 1e-3 m, normal 12.6 deg off"},
    {mjGEOM_SPHERE, mjGEOM_ELLIPSOID, DepthTrust::kRefused, "64% short at 1e-6 m"},
    {mjGEOM_SPHERE, mjGEOM_CYLINDER, DepthTrust::kRefused, "65% short at 1e-6 m, 19% deep at 1e-3 m"},
    {mjGEOM_SPHERE, mjGEOM_MESH, DepthTrust::kRefused, "73% short at 1e-6 m, 21% deep at 1e-3 m"},
    {mjGEOM_CAPSULE, mjGEOM_ELLIPSOID, DepthTrust::kRefused, "82% short at 1e-6 m"},
    {mjGEOM_CAPSULE, mjGEOM_CYLINDER, DepthTrust::kRefused, "38% short at 1e-6 m, 14% deep at 1e-3 m"},
    {mjGEOM_CAPSULE, mjGEOM_MESH, DepthTrust::kRefused, "38% short at 1e-6 m, 22% deep at 1e-3 m"},
    {mjGEOM_ELLIPSOID, mjGEOM_ELLIPSOID, DepthTrust::kRefused, "88% short at 1e-6 m"},
    {mjGEOM_ELLIPSOID, mjGEOM_CYLINDER, DepthTrust::kRefused, "66% short at 1e-6 m, 25% deep at 1e-3 m"},
    {mjGEOM_ELLIPSOID, mjGEOM_BOX, DepthTrust::kRefused, "78% short at 1e-6 m, 46% deep at 1e-3 m"},
    {mjGEOM_ELLIPSOID, mjGEOM_MESH, DepthTrust::kRefused, "78% short at 1e-6 m, 46% deep at 1e-3 m"},
    {mjGEOM_CYLINDER, mjGEOM_CYLINDER, DepthTrust::kRefused, "19% short at 1e-6 m"},
    // MPR, right from 1e-4 m on: warned
    {mjGEOM_HFIELD, mjGEOM_SPHERE, DepthTrust::kWarned,
     "its depth comes from MPR (libccd): none below ~1e-7 m, 5.7% short at 1e-6 m, within 0.06% "
     "from 1e-4 m (docs/geometry.md)"},
    {mjGEOM_HFIELD, mjGEOM_CAPSULE, DepthTrust::kWarned,
     "its depth comes from MPR (libccd): none below ~1e-7 m, 8.2% short at 1e-6 m, within 0.08% "
     "from 1e-4 m (docs/geometry.md)"},
    {mjGEOM_HFIELD, mjGEOM_CYLINDER, DepthTrust::kWarned,
     "its depth comes from MPR (libccd): none below ~1e-7 m, 7.6% short at 1e-6 m, within 0.08% "
     "from 1e-4 m (docs/geometry.md)"},
    {mjGEOM_CYLINDER, mjGEOM_BOX, DepthTrust::kWarned,
     "its depth comes from MPR (libccd): none below ~1e-7 m, 6.2% short at 1e-6 m, within 0.05% "
     "from 1e-4 m, and a face resting on a face is held at one point (docs/geometry.md)"},
    {mjGEOM_CYLINDER, mjGEOM_MESH, DepthTrust::kWarned,
     "its depth comes from MPR (libccd): none below ~1e-7 m, 6.3% short at 1e-6 m, within 0.06% "
     "from 1e-4 m, and a face resting on a face is held at one point (docs/geometry.md)"},
    // depth exact (float vertices), points short of the patch: warned
    {mjGEOM_PLANE, mjGEOM_MESH, DepthTrust::kWarned,
     "MuJoCo 2.2.2 returns at most 3 points, so a mesh face resting on the plane is held at 3 of "
     "its corners; depths exact (docs/geometry.md)"},
    // contactlaws' own when each mesh's hull is within the polytope caps
    // (ContactModel::CheckDepth says nothing then); beyond them, MuJoCo's
    {mjGEOM_BOX, mjGEOM_MESH, DepthTrust::kWarned,
     "a mesh hull beyond 64 vertices or 124 triangles is left to MuJoCo 2.2.2, which returns "
     "one point, so a face resting on a face is held at one point; depths exact "
     "(docs/geometry.md)"},
    {mjGEOM_MESH, mjGEOM_MESH, DepthTrust::kWarned,
     "a mesh hull beyond 64 vertices or 124 triangles is left to MuJoCo 2.2.2, which returns "
     "one point, so a face resting on a face is held at one point; depths exact "
     "(docs/geometry.md)"},
};

}  // namespace

const char* GeomTypeName(int type) {
  static const char* const kNames[] = {"plane",    "hfield", "sphere", "capsule",
                                       "ellipsoid", "cylinder", "box",   "mesh"};
  return type >= 0 && type < 8 ? kNames[type] : "unknown";
}

DepthVerdict JudgeDepth(int type1, int type2) {
  const int t1 = std::min(type1, type2);
  const int t2 = std::max(type1, type2);
  for (const Row& row : kRows) {
    if (row.type1 != t1 || row.type2 != t2) continue;
    DepthVerdict v;
    v.trust = row.trust;
    const std::string pair = fmt::format("{}-{}", GeomTypeName(t1), GeomTypeName(t2));
    if (row.trust == DepthTrust::kRefused) {
      v.reason = pair + ": " + fmt::format(kMprRefused, row.why);
    } else if (row.trust == DepthTrust::kWarned) {
      v.reason = pair + ": " + row.why;
    }
    return v;
  }
  return {};
}

}  // namespace contactlaws
