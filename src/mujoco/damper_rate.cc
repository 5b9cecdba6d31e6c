// Copyright contactlaws authors.

#include "mujoco/damper_rate.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

namespace contactlaws::internal {

using RowMatrix = Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

namespace {

// The dofs [first, end) of the kinematic tree of body (the world's child it
// hangs from, and that child's descendants: bodies and their dofs are
// numbered depth first); empty for the world and bodies welded to it.
std::pair<int, int> TreeDofs(const mjModel* m, int body) {
  const int root = m->body_rootid[body];
  int first = m->nv, end = 0;
  for (int b = root; root > 0 && b < m->nbody && m->body_rootid[b] == root; ++b) {
    if (m->body_dofnum[b] == 0) continue;
    first = std::min(first, m->body_dofadr[b]);
    end = std::max(end, m->body_dofadr[b] + m->body_dofnum[b]);
  }
  return first < end ? std::make_pair(first, end) : std::make_pair(0, 0);
}

// Bound's margin over the Frobenius norm: the solver's eigenvalue and the
// norm are each within a few hundred roundings (n <= a few dozen rows) of
// their exact values, the margin thousands of times that.
constexpr double kBoundMargin = 1e-9;

}  // namespace

struct DamperRate::Workspace {
  RowMatrix rows;    // 3 per point: sqrt(c) P J, one row per world axis
  RowMatrix solved;  // D^-1/2 L^-T rows^T (M = L^T D L), one row per row
  RowMatrix jac[2];  // a point's Jacobian on each body
  Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic> product;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic>> solver;
  bool empty = true;  // no dofs or no points: lambda_max 0
};

DamperRate::DamperRate() : w_(std::make_unique<Workspace>()) {}
DamperRate::~DamperRate() = default;

double DamperRate::Rate(const mjModel* m, mjData* d, const GeomPair& pair, int points,
                        const mjtNum* pos, const mjtNum* normal, const double* damping,
                        DamperDirection direction) {
  Bound(m, d, pair, points, pos, normal, damping, direction);
  return MaxEigenvalue();
}

double DamperRate::Bound(const mjModel* m, mjData* d, const GeomPair& pair, int points,
                         const mjtNum* pos, const mjtNum* normal, const double* damping,
                         DamperDirection direction) {
  const int nv = m->nv;
  const int n = 3 * points;
  Workspace& w = *w_;
  w.empty = nv == 0 || n == 0;
  if (w.empty) return 0;
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
  // half of M^-1 for each row, then the n x n symmetric product rows M^-1
  // rows^T = solved solved^T and its largest eigenvalue (its others are not
  // needed, nor its vectors). M is block diagonal over the world's children:
  // solved is 0 outside the two bodies' trees' dofs, so the product sums
  // over those alone (a ball among 64 free ones: 12 of 384 dofs).
  mj_solveM2(m, d, w.solved.data(), w.rows.data(), n);
  w.product.setZero(n, n);
  const std::pair<int, int> trees[2] = {TreeDofs(m, pair.body[0]), TreeDofs(m, pair.body[1])};
  for (int t = 0; t < 2; ++t) {
    const auto [first, end] = trees[t];
    if (first == end || (t == 1 && trees[1] == trees[0])) continue;
    const auto block = w.solved.middleCols(first, end - first);
    w.product.noalias() += block * block.transpose();
  }
  // the Frobenius norm of the matrix the eigenvalue solver reads (its lower
  // triangle, mirrored): sqrt(sum lambda_i^2) >= lambda_max
  double squares = 0;
  for (int j = 0; j < n; ++j) {
    squares += w.product(j, j) * w.product(j, j);
    for (int i = j + 1; i < n; ++i) squares += 2 * w.product(i, j) * w.product(i, j);
  }
  return std::sqrt(squares) * (1 + kBoundMargin);
}

double DamperRate::MaxEigenvalue() {
  Workspace& w = *w_;
  if (w.empty) return 0;
  w.solver.compute(w.product, Eigen::EigenvaluesOnly);
  return std::max(w.solver.eigenvalues().maxCoeff(), 0.0);
}

}  // namespace contactlaws::internal
