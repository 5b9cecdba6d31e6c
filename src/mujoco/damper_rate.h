// Copyright contactlaws authors.
//
// How fast the dampers of a pair's contact points act on its bodies: the
// rate an explicit step must resolve. Dampers c_j at points p_j that resist
// the relative tangential (friction's) or normal (the laws') velocity of the
// pair's two bodies make the velocities decay as exp(-lambda t), lambda an
// eigenvalue of
//   C^(1/2) P J M^-1 J^T P C^(1/2),
// J the points' relative Jacobians (body[1] minus body[0]), P the projections
// on their tangent planes (I - n n^T) or on their normals (n n^T), M the
// mass matrix. A box resting on four corners rocks against its normal
// dampers 3x faster than it moves its mass against them (a 1 x 1 x 0.1 m
// plate). The points act in parallel,
// and through the bodies' rotations as well as their translations: a cube
// resting on its four corners turns about the vertical against its dampers
// at 12 c / m, where one of them on the cube's mass acts at c / m. RK4 is
// stable up to 2.785 / lambda_max.

#ifndef CONTACTLAWS_MUJOCO_DAMPER_RATE_H_
#define CONTACTLAWS_MUJOCO_DAMPER_RATE_H_

#include <memory>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/contact_model.h"

namespace contactlaws::internal {

// Which part of the points' relative velocity the dampers resist.
enum class DamperDirection { kTangential, kNormal };

class DamperRate {
 public:
  DamperRate();
  ~DamperRate();

  // lambda_max (1/s) for the dampers damping[j] (N s/m, >= 0) at points
  // pos[3 j ..] with unit normals normal[3 j ..] of pair, j < points, at d's
  // state: its positions' Jacobians and its factorized mass matrix (qLD:
  // after mj_forward or a step). 0 when nothing can move. Allocates only
  // when a pair has more points than any before or when the size of the
  // matrix it solves changes (the smaller of the points' rows, one per
  // point and damped direction, and the two bodies' trees' dofs); Bound only
  // in the first case.
  double Rate(const mjModel* m, mjData* d, const GeomPair& pair, int points,
              const mjtNum* pos, const mjtNum* normal, const double* damping,
              DamperDirection direction = DamperDirection::kTangential);

  // An upper bound of Rate's lambda_max for the same arguments, at a
  // fraction of its cost (no eigenvalue solve), for a caller that needs the
  // rate only when it is large (AutoTimestep: a lag that binds the step).
  // The Frobenius norm sqrt(sum lambda_i^2) of the same matrix formed with
  // one row per point and direction, (J1 - J0)^T u for u the normal or two
  // tangents (the same nonzero eigenvalues as the three rows of the
  // projection), plus a margin of 1e-9 of its trace for the roundings: at
  // least what Rate returns, at most sqrt(rank) times it and the margin.
  double Bound(const mjModel* m, mjData* d, const GeomPair& pair, int points,
               const mjtNum* pos, const mjtNum* normal, const double* damping,
               DamperDirection direction);

  // An upper bound of Bound's trace, so of Rate's lambda_max, for pairs whose
  // bodies are each static or a single free body (infinite otherwise), from
  // the points' distances alone (no Jacobian, no solve): a free body's
  // inverse inertia at a point r from its centre of mass, 1/m + [r]x I^-1
  // [r]x^T, acts on any direction at most by 1/m + |r|^2 / I_min, so
  // lambda_max <= sum_j c_j (rows per point) sum_bodies (1/m + |r_j|^2 /
  // I_min), with Bound's margin. For a caller to try before Bound.
  // Rate of the dampers the last Bound took, at the same state: Bound's rows
  // and halves reused (a caller whose bound did not decide goes on to the
  // exact rate without forming them again).
  double RateAfterBound(const mjModel* m);

  double InertiaBound(const mjModel* m, const mjData* d, const GeomPair& pair, int points,
                      const mjtNum* pos, const double* damping,
                      DamperDirection direction) const;

 private:
  // The rows sqrt(c_j) (J1 - J0)^T u, u the normal or two tangents at each
  // point (k of them, returned), and their halves D^-1/2 L^-T of M^-1, row by
  // row, in the workspace; with the two bodies' trees' dofs, the columns
  // outside which the halves are 0.
  // The largest eigenvalue of the halves' Gram matrix (k rows of nv).
  double LargestEigenvalue(int k, int nv);
  int Halves(const mjModel* m, mjData* d, const GeomPair& pair, int points, const mjtNum* pos,
             const mjtNum* normal, const double* damping, DamperDirection direction);

  struct Workspace;
  std::unique_ptr<Workspace> w_;
  int rows_ = 0;  // the rows of the last Bound (RateAfterBound)
};

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_MUJOCO_DAMPER_RATE_H_
