// Copyright contactlaws authors.

#include "mujoco/kinematics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "mujoco/vec3.h"

namespace contactlaws {
using vec3::Cross;
using vec3::Dot;
using vec3::Sub;

void AddPointForce(const mjModel* m, const mjData* d, int body, const mjtNum point[3],
                   const mjtNum force[3], mjtNum* qfrc) {
  // the body's nearest ancestor (itself included) with dofs: its last dof
  int b = body;
  while (b > 0 && m->body_dofnum[b] == 0) b = m->body_parentid[b];
  if (b <= 0) return;  // welded to the world (mocap bodies too): no dofs
  // qfrc_j += f . (lin_j + ang_j x r) = f . lin_j + ang_j . (r x f), with
  // cdof_j = (ang_j, lin_j) at the subtree com of the body's root
  mjtNum r[3], moment[3];
  Sub(r, point, d->subtree_com + 3 * m->body_rootid[body]);
  Cross(moment, r, force);
  for (int j = m->body_dofadr[b] + m->body_dofnum[b] - 1; j >= 0; j = m->dof_parentid[j]) {
    const mjtNum* cdof = d->cdof + 6 * j;
    qfrc[j] += Dot(cdof, moment) + Dot(cdof + 3, force);
  }
}

void AddTorque(const mjModel* m, const mjData* d, int body, const mjtNum torque[3], mjtNum* qfrc) {
  int b = body;
  while (b > 0 && m->body_dofnum[b] == 0) b = m->body_parentid[b];
  if (b <= 0) return;  // welded to the world: no dofs
  // qfrc_j += ang_j . torque, cdof_j = (ang_j, lin_j)
  for (int j = m->body_dofadr[b] + m->body_dofnum[b] - 1; j >= 0; j = m->dof_parentid[j]) {
    qfrc[j] += Dot(d->cdof + 6 * j, torque);
  }
}

bool SingleFreeBody(const mjModel* m, int body) {
  return body > 0 && m->body_parentid[body] == 0 && m->body_jntnum[body] == 1 &&
         m->jnt_type[m->body_jntadr[body]] == mjJNT_FREE &&
         (body + 1 == m->nbody || m->body_rootid[body + 1] != body);
}

bool OnlySingleFreeBodies(const mjModel* m) {
  if (m->nmocap > 0) return false;
  for (int b = 1; b < m->nbody; ++b) {
    if (m->body_weldid[b] != 0 && !SingleFreeBody(m, b)) return false;
  }
  return true;
}

__attribute__((optimize("fp-contract=off"))) void NormalizeQuaternion(mjtNum q[4]) {
  const mjtNum norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (norm < mjMINVAL) {
    q[0] = 1;
    q[1] = q[2] = q[3] = 0;
    return;
  }
  const mjtNum inverse = 1 / norm;
  for (int i = 0; i < 4; ++i) q[i] *= inverse;
}

double FreeBodyKinematics(const mjModel* m, mjData* d) {
  // mj_kinematics normalizes qpos's quaternion, then its copy: every body's
  // first, in a loop of their own, where one body's square root and division
  // need not wait for another's
  for (int b = 1; b < m->nbody; ++b) {
    if (!SingleFreeBody(m, b)) continue;
    mjtNum* quat = d->qpos + m->jnt_qposadr[m->body_jntadr[b]] + 3;
    mjtNum* xquat = d->xquat + 4 * b;
    NormalizeQuaternion(quat);
    mju_copy4(xquat, quat);
    NormalizeQuaternion(xquat);
  }
  double kinetic = 0;
  for (int b = 1; b < m->nbody; ++b) {
    if (!SingleFreeBody(m, b)) continue;
    const int joint = m->body_jntadr[b];
    mjtNum* qpos = d->qpos + m->jnt_qposadr[joint];
    // qvel: the frame origin's velocity (world frame), then the angular
    // velocity (body frame)
    const mjtNum* qvel = d->qvel + m->jnt_dofadr[joint];
    mjtNum* xpos = d->xpos + 3 * b;
    mjtNum* xquat = d->xquat + 4 * b;
    mjtNum* xmat = d->xmat + 9 * b;
    mjtNum* xipos = d->xipos + 3 * b;
    mju_copy3(xpos, qpos);
    mju_quat2Mat(xmat, xquat);
    mj_local2Global(d, xipos, d->ximat + 9 * b, m->body_ipos + 3 * b, m->body_iquat + 4 * b, b,
                    m->body_sameframe[b]);
    mju_copy3(d->subtree_com + 3 * b, xipos);
    // cvel at the com: (R w, v + R w x (xipos - xpos))
    mjtNum* cvel = d->cvel + 6 * b;
    mjtNum offset[3], turn[3];
    mju_rotVecMat(cvel, qvel + 3, xmat);
    Sub(offset, xipos, xpos);
    Cross(turn, cvel, offset);
    for (int i = 0; i < 3; ++i) cvel[3 + i] = qvel[i] + turn[i];
    // the body-frame angular velocity in the principal axes (iquat^-1 w)
    mjtNum inverse[4], principal[3];
    mju_negQuat(inverse, m->body_iquat + 4 * b);
    mju_rotVecQuat(principal, qvel + 3, inverse);
    const mjtNum* inertia = m->body_inertia + 3 * b;
    kinetic += 0.5 * (m->body_mass[b] * Dot(cvel + 3, cvel + 3) +
                      inertia[0] * principal[0] * principal[0] +
                      inertia[1] * principal[1] * principal[1] +
                      inertia[2] * principal[2] * principal[2]);
  }
  return kinetic;
}

void PointVelocity(const ContactModel& model, const mjData* d, int body, const mjtNum point[3],
                   mjtNum vel[3]) {
  const mjModel* m = model.model();
  if (const Drive* drive = model.FindDrive(body)) {
    drive->Velocity(d->time, vel);
    return;
  }
  if (m->body_weldid[body] == 0) {
    vel[0] = vel[1] = vel[2] = 0;
    return;
  }
  // cvel: (angular, linear) velocity at the subtree com of the body's root
  const mjtNum* cvel = d->cvel + 6 * body;
  mjtNum offset[3], turn[3];
  Sub(offset, point, d->subtree_com + 3 * m->body_rootid[body]);
  Cross(turn, cvel, offset);
  for (int i = 0; i < 3; ++i) vel[i] = cvel[3 + i] + turn[i];
}

void AddPointJacobianRate(const mjModel* m, const mjData* d, int body, const mjtNum point[3],
                          const mjtNum direction[3], mjtNum* row) {
  int b = body;
  while (b > 0 && m->body_dofnum[b] == 0) b = m->body_parentid[b];
  if (b <= 0) return;  // welded to the world: no dofs
  // the point's offset from the root's subtree com (where cdof and cvel
  // are taken) and its velocity
  const mjtNum* cvel = d->cvel + 6 * body;
  mjtNum r[3], vel[3], turn[3];
  Sub(r, point, d->subtree_com + 3 * m->body_rootid[body]);
  Cross(turn, cvel, r);
  for (int i = 0; i < 3; ++i) vel[i] = cvel[3 + i] + turn[i];
  // direction . (lin' + rot' x r + rot x vel) = direction . lin'
  //   + rot' . (r x direction) + rot . (vel x direction)
  mjtNum r_dir[3], vel_dir[3];
  Cross(r_dir, r, direction);
  Cross(vel_dir, vel, direction);
  for (int j = m->body_dofadr[b] + m->body_dofnum[b] - 1; j >= 0; j = m->dof_parentid[j]) {
    const mjtNum* dot = d->cdof_dot + 6 * j;
    row[j] += Dot(dot + 3, direction) + Dot(dot, r_dir) + Dot(d->cdof + 6 * j, vel_dir);
  }
}

namespace {

// A cylinder's contact point is on its rim (or its side) when it lies at
// least this share of the radius from the axis, and the rim is no flat face
// on the other surface when the axis is at least this sine away from the
// normal (a cylinder standing on its face: its rim points are the face's
// material points).
constexpr double kRimShare = 0.5;
constexpr double kFlatSine = 0.05;

}  // namespace

void AddDepthJacobianRate(const mjModel* m, const mjData* d, int body, int g,
                          const double pos[3], const double direction[3], double* row) {
  const int type = m->geom_type[g];
  const mjtNum* xpos = d->geom_xpos + 3 * g;
  if (type == mjGEOM_SPHERE) {
    AddPointJacobianRate(m, d, body, xpos, direction, row);
    return;
  }
  if (type == mjGEOM_ELLIPSOID) {
    // the support point p = c + R s(u), u = R^T direction, s(u) = A^2 u / q,
    // q = |A u|, A the semi-axes: besides its material point's
    // acceleration, it rolls over the surface at R S u', S = ds/du =
    // (A^2 - A^2 u u^T A^2 / q^2) / q (S u = 0 along u), u' = -w_body x u,
    // which adds (w x n)^T R S R^T (w x n) to n . p'' (n = direction, w the
    // spin): a torque row n x (R S R^T (w x n)). For a sphere (S = r (I -
    // u u^T)) it cancels the material point's centripetal term, as a
    // sphere's centre gives it.
    AddPointJacobianRate(m, d, body, pos, direction, row);
    const mjtNum* xmat = d->geom_xmat + 9 * g;
    const mjtNum* size = m->geom_size + 3 * g;
    const mjtNum* spin = d->cvel + 6 * body;
    double u[3], turn[3], turn_local[3];
    mju_mulMatTVec(u, xmat, direction, 3, 3);
    mju_cross(turn, spin, direction);
    mju_mulMatTVec(turn_local, xmat, turn, 3, 3);
    double q2 = 0, along = 0;  // |A u|^2, u^T A^2 (w x n)
    for (int k = 0; k < 3; ++k) {
      const double a2 = size[k] * size[k];
      q2 += a2 * u[k] * u[k];
      along += a2 * u[k] * turn_local[k];
    }
    if (!(q2 > 0)) return;
    const double q = std::sqrt(q2);
    double rolled_local[3], rolled[3], torque[3];
    for (int k = 0; k < 3; ++k) {
      const double a2 = size[k] * size[k];
      rolled_local[k] = (a2 * turn_local[k] - a2 * u[k] * along / q2) / q;
    }
    mju_mulMatVec(rolled, xmat, rolled_local, 3, 3);
    mju_cross(torque, direction, rolled);
    AddTorque(m, d, body, torque, row);
    return;
  }
  if (type != mjGEOM_CAPSULE && type != mjGEOM_CYLINDER) {
    AddPointJacobianRate(m, d, body, pos, direction, row);
    return;
  }
  // the geom's axis (its frame's z) and the nearest axis point
  const mjtNum* xmat = d->geom_xmat + 9 * g;
  const double a[3] = {xmat[2], xmat[5], xmat[8]};
  double offset[3], c[3];
  vec3::Sub(offset, pos, xpos);
  const double half = m->geom_size[3 * g + 1];
  const double along = std::clamp(vec3::Dot(offset, a), -half, half);
  for (int k = 0; k < 3; ++k) c[k] = xpos[k] + along * a[k];
  if (type == mjGEOM_CAPSULE) {
    AddPointJacobianRate(m, d, body, c, direction, row);
    return;
  }
  double radial[3];
  vec3::Sub(radial, pos, c);
  const double da = vec3::Dot(direction, a);
  const double sine = std::sqrt(std::max(0.0, 1 - da * da));
  const double radius = m->geom_size[3 * g];
  if (mju_norm3(radial) < kRimShare * radius || sine < kFlatSine) {
    AddPointJacobianRate(m, d, body, pos, direction, row);
    return;
  }
  AddPointJacobianRate(m, d, body, c, direction, row);
  // -r (delta . a)(delta . (w x a)) / s, differentiated with w held:
  // -r [k^2 + (delta . a)(delta . (w x a'))] / s - r (delta . a)^2 k^2 / s^3,
  // k = delta . a', a' = w x a; as a row in w: torque . w
  const mjtNum* spin = d->cvel + 6 * body;
  double turn[3], a_delta[3], turn_delta[3];
  mju_cross(turn, spin, a);
  const double k = vec3::Dot(direction, turn);
  mju_cross(a_delta, a, direction);
  mju_cross(turn_delta, turn, direction);
  double torque[3];
  for (int i = 0; i < 3; ++i) {
    torque[i] = -radius / sine * (k * a_delta[i] + da * turn_delta[i]) -
                radius * da * da * k / (sine * sine * sine) * a_delta[i];
  }
  AddTorque(m, d, body, torque, row);
}

void PointInBodies(const mjData* d, const GeomPair& pair, const mjtNum pos[3], double on0[3],
                   double on1[3]) {
  double* on[2] = {on0, on1};
  for (int b = 0; b < 2; ++b) {
    mjtNum offset[3];
    Sub(offset, pos, d->xpos + 3 * pair.body[b]);
    vec3::RotateTransposed(on[b], offset, d->xmat + 9 * pair.body[b]);
  }
}

void ReadContactPoint(const ContactModel& model, const mjData* d, int p, const mjContact& con,
                      PointEvaluation* e, mjtNum v0[3], mjtNum v1[3]) {
  const GeomPair& pair = model.pairs()[p];
  e->pair = p;
  e->tag = pair.tag;
  e->depth = -con.dist;
  // which physical point: where it sits on the two bodies
  PointInBodies(d, pair, con.pos, e->local[0], e->local[1]);
  // depth rate: approach speed of geom[0] towards geom[1] along the normal
  PointVelocity(model, d, pair.body[0], con.pos, v0);
  PointVelocity(model, d, pair.body[1], con.pos, v1);
  mjtNum relative[3];
  Sub(relative, v0, v1);
  e->depth_rate = Dot(relative, con.frame);
}

void NormalJacobian(const mjModel* m, const mjData* d, const GeomPair& pair, const mjtNum point[3],
                    const mjtNum normal[3], mjtNum* jn) {
  // (J1 - J0)^T n is the generalized force of a unit force n at point on
  // body[1] and -n on body[0]: each body's chain alone, not two 3 x nv
  // Jacobians (this runs for every point of every stage)
  mju_zero(jn, m->nv);
  mjtNum opposite[3];
  mju_scl3(opposite, normal, -1);
  AddPointForce(m, d, pair.body[0], point, opposite, jn);
  AddPointForce(m, d, pair.body[1], point, normal, jn);
}

double EffectiveMass(const mjModel* m, mjData* d, const GeomPair& pair, const mjtNum point[3],
                     const mjtNum normal[3]) {
  // 1 / (n^T J M^-1 J^T n), J the relative Jacobian at point
  const int nv = m->nv;
  const int mark = d->pstack;
  Eigen::Map<Eigen::VectorX<mjtNum>> jn(mj_stackAlloc(d, nv), nv);
  Eigen::Map<Eigen::VectorX<mjtNum>> x(mj_stackAlloc(d, nv), nv);
  NormalJacobian(m, d, pair, point, normal, jn.data());
  mj_solveM(m, d, x.data(), jn.data(), 1);
  const double inverse_mass = jn.dot(x);
  d->pstack = mark;
  return inverse_mass > 0 ? 1.0 / inverse_mass : std::numeric_limits<double>::infinity();
}

double ApproachRate(const ContactModel& model, mjData* d, const GeomPair& pair,
                    const mjtNum point[3], const mjtNum normal[3], const mjtNum* qvel,
                    double time) {
  const mjModel* m = model.model();
  // (v0 - v1) . n = -(n^T (J1 - J0)) qvel for the dofs; driven bodies through
  // their prescribed velocity at time
  const int nv = m->nv;
  const int mark = d->pstack;
  mjtNum* jn = mj_stackAlloc(d, nv);
  NormalJacobian(m, d, pair, point, normal, jn);
  double rate = -mju_dot(jn, qvel, nv);
  d->pstack = mark;
  mjtNum drive_velocity[3];
  if (const Drive* drive = model.FindDrive(pair.body[0])) {
    drive->Velocity(time, drive_velocity);
    rate += mju_dot3(drive_velocity, normal);
  }
  if (const Drive* drive = model.FindDrive(pair.body[1])) {
    drive->Velocity(time, drive_velocity);
    rate -= mju_dot3(drive_velocity, normal);
  }
  return rate;
}

void ApplyDrives(const ContactModel& model, mjData* d) {
  const mjModel* m = model.model();
  for (const Drive& drive : model.drives()) {
    mjtNum pos[3], delta[3];
    drive.Position(d->time, pos);
    mju_sub3(delta, pos, d->xpos + 3 * drive.body);
    mju_addTo3(d->xpos + 3 * drive.body, delta);
    mju_addTo3(d->xipos + 3 * drive.body, delta);
    const int first = m->body_geomadr[drive.body];
    for (int g = first; g < first + m->body_geomnum[drive.body]; ++g) {
      mju_addTo3(d->geom_xpos + 3 * g, delta);
    }
  }
}

bool BoundingGap(const mjModel* m, const mjData* d, int g0, int g1, double* gap,
                 mjtNum normal[3]) {
  const mjtNum r0 = m->geom_rbound[g0];
  const mjtNum r1 = m->geom_rbound[g1];
  const mjtNum* p0 = d->geom_xpos + 3 * g0;
  const mjtNum* p1 = d->geom_xpos + 3 * g1;
  if (r0 > 0 && r1 > 0) {
    mju_sub3(normal, p1, p0);
    *gap = mju_normalize3(normal) - r0 - r1;
    return true;
  }
  // a plane's sphere is unbounded (rbound 0): the other's height above it
  for (const int plane : {0, 1}) {
    const int g = plane == 0 ? g0 : g1;
    const mjtNum r = plane == 0 ? r1 : r0;
    if (m->geom_type[g] != mjGEOM_PLANE || !(r > 0)) continue;
    // the plane's normal (its z axis), from g0 towards g1
    const mjtNum* mat = d->geom_xmat + 9 * g;
    const mjtNum sign = plane == 0 ? 1.0 : -1.0;
    normal[0] = sign * mat[2];
    normal[1] = sign * mat[5];
    normal[2] = sign * mat[8];
    const mjtNum* q = plane == 0 ? p1 : p0;  // the other geom's centre
    const mjtNum* o = plane == 0 ? p0 : p1;  // a point of the plane
    *gap = (q[0] - o[0]) * mat[2] + (q[1] - o[1]) * mat[5] + (q[2] - o[2]) * mat[8] - r;
    return true;
  }
  return false;
}

bool FarApart(const mjModel* m, const mjData* d, int g1, int g2) {
  double gap;
  mjtNum normal[3];
  return BoundingGap(m, d, g1, g2, &gap, normal) && gap > 0;
}

}  // namespace contactlaws
