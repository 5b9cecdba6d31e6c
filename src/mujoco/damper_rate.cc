// Copyright contactlaws authors.

#include "mujoco/damper_rate.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

namespace contactlaws::internal {

using RowMatrix = Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct DamperRate::Workspace {
  RowMatrix rows;    // 3 per point: sqrt(c) P J, one row per world axis
  RowMatrix solved;  // M^-1 rows^T, one row per row
  RowMatrix jac[2];  // a point's Jacobian on each body
  Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic> product;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic>> solver;
};

DamperRate::DamperRate() : w_(std::make_unique<Workspace>()) {}
DamperRate::~DamperRate() = default;

double DamperRate::Rate(const mjModel* m, mjData* d, const GeomPair& pair,
                                  int points, const mjtNum* pos, const mjtNum* normal,
                                  const double* damping, DamperDirection direction) {
  const int nv = m->nv;
  const int n = 3 * points;
  if (nv == 0 || n == 0) return 0;
  Workspace& w = *w_;
  w.rows.resize(n, nv);
  w.solved.resize(n, nv);
  for (RowMatrix& jac : w.jac) jac.resize(3, nv);
  for (int j = 0; j < points; ++j) {
    // the relative velocity at the point per dof, its tangential part
    // (I - n n^T) (J1 - J0) or its normal part n n^T (J1 - J0), scaled by
    // sqrt(c)
    for (int b = 0; b < 2; ++b) {
      mj_jac(m, d, w.jac[b].data(), nullptr, pos + 3 * j, pair.body[b]);
    }
    const Eigen::Map<const Eigen::Vector3<mjtNum>> unit(normal + 3 * j);
    const Eigen::Matrix3<mjtNum> along = unit * unit.transpose();
    const Eigen::Matrix3<mjtNum> plane = direction == DamperDirection::kNormal
                                             ? along
                                             : Eigen::Matrix3<mjtNum>(
                                                   Eigen::Matrix3<mjtNum>::Identity() - along);
    w.rows.middleRows(3 * j, 3).noalias() =
        std::sqrt(std::max(damping[j], 0.0)) * plane * (w.jac[1] - w.jac[0]);
  }
  // M^-1 for each row, then the n x n symmetric product and its largest
  // eigenvalue (its others are not needed, nor its vectors)
  mj_solveM(m, d, w.solved.data(), w.rows.data(), n);
  w.product.noalias() = w.rows * w.solved.transpose();
  w.solver.compute(w.product, Eigen::EigenvaluesOnly);
  return std::max(w.solver.eigenvalues().maxCoeff(), 0.0);
}

}  // namespace contactlaws::internal
