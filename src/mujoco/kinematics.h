// Copyright contactlaws authors.
//
// The kinematics the laws need from MuJoCo, at the state of an mjData (inside
// the hooks, or after mj_forward): the velocity of a point on a body, the
// approach rate and effective mass of a pair along a normal, a force applied
// at a point, and the driven bodies' prescribed motion.

#ifndef CONTACTLAWS_KINEMATICS_H_
#define CONTACTLAWS_KINEMATICS_H_

#include <algorithm>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/contact_model.h"
#include "contactlaws/impact.h"

namespace contactlaws {

// qfrc += J^T force for a world-frame force at a world point fixed to body:
// what mj_applyFT(m, d, force, 0, point, body, qfrc) adds, walking only the
// dofs of the body's chain (O(depth of the tree), not O(nv)). Needs cdof and
// subtree_com (mj_comPos; current inside the hooks).
void AddPointForce(const mjModel* m, const mjData* d, int body, const mjtNum point[3],
                   const mjtNum force[3], mjtNum* qfrc);

// qfrc += J_rot^T torque for a world-frame torque on body (what
// mj_applyFT(m, d, 0, torque, ...) adds), walking only the body's chain.
void AddTorque(const mjModel* m, const mjData* d, int body, const mjtNum torque[3], mjtNum* qfrc);

// Whether body is a free body alone in its tree: its own free joint, from the
// world, no bodies below it (its inertia is its own).
bool SingleFreeBody(const mjModel* m, int body);

// True when every body that moves is a single free body (SingleFreeBody) and
// none is driven (no mocap bodies): FreeBodyKinematics then gives every
// moving body's kinematics.
bool OnlySingleFreeBodies(const mjModel* m);

// mju_normalize4's arithmetic, inline: the same bits (the norm's sum in the
// same order, unfused; then times its inverse; (1, 0, 0, 0) below mjMINVAL).
void NormalizeQuaternion(mjtNum q[4]);

// For every single free body, from d's qpos (its quaternion normalized in
// place, as mj_kinematics does) and qvel, what a trajectory row
// reads, without the rest of MuJoCo's pipeline (positions of geoms and sites,
// cdof, cinert, cdof_dot, the mass matrix): xpos, xquat, xmat, xipos and
// ximat from the calls mj_kinematics makes (the same bits); subtree_com
// (xipos) and cvel ((angular, linear) at the com, world frame) equal to
// mj_comPos's and mj_comVel's to rounding. Returns their kinetic energy, 1/2
// qvel^T M qvel to rounding: 1/2 m |v_com|^2 + 1/2 w^T I w, w in the body's
// principal axes. Leaves every other body, geom and site as it is.
double FreeBodyKinematics(const mjModel* m, mjData* d);

// World-frame velocity of a point fixed to body (driven bodies: their
// prescribed motion at d->time). Needs cvel.
void PointVelocity(const ContactModel& model, const mjData* d, int body, const mjtNum point[3],
                   mjtNum vel[3]);

// row += direction^T dJ/dt at point: the rate of change of the Jacobian of
// the point fixed to body (world frame), projected on direction, walking only
// the body's chain. Column k of dJ/dt is cdof_dot_k at the point plus
// (cdof_k's rotation) x (the point's velocity); row . qvel is then the
// point's acceleration at q'' = 0 along direction (mj_objectAcceleration's).
// Needs cdof_dot (mj_comVel) and cvel; driven bodies and the world: nothing.
void AddPointJacobianRate(const mjModel* m, const mjData* d, int body, const mjtNum point[3],
                          const mjtNum direction[3], mjtNum* row);

// Adds to row the moving Jacobian J' of the depth of a contact on geom g of
// body at pos, the depth growing along -direction there (its contribution
// direction . p'' to the normal row), at the point that carries it: where
// the surface is smooth and the contact point rolls over it, not the
// material point at the contact, whose centripetal r w^2 the contact never
// sees (a capsule rolling at 50 rad/s took 75 m/s^2 of lift a step, and its
// ledger booked 0.48 J of damping in 0.3 s that dissipates nothing).
//  - A sphere: its centre.
//  - A capsule: the nearest point of its segment, c: the contact point is
//    c + R direction, whose depth moves as c does.
//  - A cylinder on its rim or side: the contact point is the rim circle's
//    point most along direction, p = c + r u, c the circle's centre on the
//    axis a, u = (direction - (direction . a) a) / s, s = |...|; direction
//    . p = direction . c + r s moves as c does and as the axis tilts:
//    J' at c, and the derivative of -r (direction . a)(direction . (w x a))
//    / s at the body's spin w, a torque row (AddTorque).
//  - An ellipsoid: its support point along direction, which rolls over the
//    surface (at its curvature) as the body turns: the material point's J'
//    and a torque row for the rolling.
//  - Elsewhere (a vertex, an edge, a face's point, a cylinder's face): the
//    contact point, a material point.
void AddDepthJacobianRate(const mjModel* m, const mjData* d, int body, int g,
                          const double pos[3], const double direction[3], double* row);

// Where the point pos sits on pair's two bodies, in their frames (on0: body
// 0's, on1: body 1's), as ReadContactPoint's PointEvaluation::local.
void PointInBodies(const mjData* d, const GeomPair& pair, const mjtNum pos[3], double on0[3],
                   double on1[3]);

// A narrowphase contact of ContactModel pair p read into e: its pair, tag,
// depth (-con.dist), place on each body (local) and depth rate along
// con.frame; v0 and v1 get the two bodies' velocities at con.pos, for a
// caller that also wants the slip. Needs cvel.
void ReadContactPoint(const ContactModel& model, const mjData* d, int p, const mjContact& con,
                      PointEvaluation* e, mjtNum v0[3], mjtNum v1[3]);

// jn = (J1 - J0)^T n at point (nv entries): the normal relative velocity of
// pair's bodies per dof (AddPointForce's map of a unit force).
void NormalJacobian(const mjModel* m, const mjData* d, const GeomPair& pair, const mjtNum point[3],
                    const mjtNum normal[3], mjtNum* jn);

// 1 / (n^T J M^-1 J^T n) at a point, for the two bodies of pair (infinite
// when neither can move along n).
double EffectiveMass(const mjModel* m, mjData* d, const GeomPair& pair, const mjtNum point[3],
                     const mjtNum normal[3]);

// d' at point along normal for the velocities qvel (driven bodies: their
// prescribed velocity at time), with the current configuration's Jacobians.
double ApproachRate(const ContactModel& model, mjData* d, const GeomPair& pair,
                    const mjtNum point[3], const mjtNum normal[3], const mjtNum* qvel,
                    double time);

// The gap between the bounding volumes of geoms g0 and g1 at d, as MuJoCo's
// broadphase bounds them (margin 0): two bounding spheres (geom_rbound), or a
// plane (rbound 0) and the other geom's sphere. *gap: m, < 0 when they
// overlap; normal: the unit direction from g0 towards g1 across it (the
// centres', or the plane's normal). False, and nothing written, when neither
// geom has a bounding sphere (two planes, height fields): the pair is always
// near.
bool BoundingGap(const mjModel* m, const mjData* d, int g0, int g1, double* gap,
                 mjtNum normal[3]);

// The "is this pair near" test of the passive hook: true when the bounding
// volumes of g1 and g2 (BoundingGap) are apart, so that they cannot touch.
bool FarApart(const mjModel* m, const mjData* d, int g1, int g2);

// Translates each driven body (and its geoms) to its pose at d->time: exact
// at every RK4 stage, where mocap_pos still holds the step's start.
void ApplyDrives(const ContactModel& model, mjData* d);

// Keeps d->qpos through the forward passes done to read a state (a
// trajectory's row, a dense output's capture): mj_kinematics normalizes
// qpos's quaternions in place (MuJoCo 2.2), and normalizing is not
// idempotent in floating point (a normalized quaternion's norm is 1 to
// rounding, and dividing by it again can move its last bit). A read that
// wrote qpos made the run depend on its output: box_stack.xml under
// contact steps gave a first e_post of 0.197475 with --output and 0.197473
// without. The positions are saved into saved (no allocation once it has
// grown) and restored when this object goes.
class PositionsKept {
 public:
  PositionsKept(const mjModel* m, mjData* d, std::vector<mjtNum>* saved)
      : d_(d), saved_(saved) {
    saved_->assign(d->qpos, d->qpos + m->nq);
  }
  ~PositionsKept() { std::copy(saved_->begin(), saved_->end(), d_->qpos); }
  PositionsKept(const PositionsKept&) = delete;
  PositionsKept& operator=(const PositionsKept&) = delete;

 private:
  mjData* d_;
  std::vector<mjtNum>* saved_;
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_KINEMATICS_H_
