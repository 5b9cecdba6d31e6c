// Copyright contactlaws authors.

#include "mujoco/damper_rate.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "mujoco/kinematics.h"

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

// Bound's margin, a share of the matrix's trace (>= its Frobenius norm): the
// eigenvalue Rate computes and the norm Bound computes, of two matrices equal
// in exact arithmetic, are each within some hundreds of roundings (1e-16) of
// that scale; the margin is thousands of times that.
constexpr double kBoundMargin = 1e-9;

// Two unit tangents t[0..2], t[3..5] orthogonal to the unit normal n and to
// each other.
void Tangents(const mjtNum n[3], mjtNum t[6]) {
  // the axis least along n, its part across n
  int axis = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(n[i]) < std::abs(n[axis])) axis = i;
  }
  mjtNum e[3] = {0, 0, 0};
  e[axis] = 1;
  mju_cross(t, n, e);
  mju_normalize3(t);
  mju_cross(t + 3, n, t);
}

}  // namespace

struct DamperRate::Workspace {
  RowMatrix rows;    // 3 per point: sqrt(c) P J, one row per world axis
  RowMatrix solved;  // D^-1/2 L^-T rows^T (M = L^T D L), one row per row
  RowMatrix jac[2];  // a point's Jacobian on each body
  RowMatrix columns; // solved's columns of the two bodies' trees' dofs
  Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic> product;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic>> solver;
  // Bound's: sqrt(c) (J1 - J0)^T u per point and direction u, and their halves
  // D^-1/2 L^-T of M^-1, row by row (vectors: their capacity stays)
  std::vector<mjtNum> forces, halves;
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
  // half of M^-1 for each row: solved, whose Gram matrix solved solved^T
  // (n x n) is rows M^-1 rows^T. M is block diagonal over the world's
  // children: solved is 0 outside the two bodies' trees' dofs, so only those
  // columns count (a ball among 64 free ones: 12 of 384 dofs).
  mj_solveM2(m, d, w.solved.data(), w.rows.data(), n);
  const std::pair<int, int> trees[2] = {TreeDofs(m, pair.body[0]), TreeDofs(m, pair.body[1])};
  int dofs = 0;
  for (int t = 0; t < 2; ++t) {
    const auto [first, end] = trees[t];
    if (t == 1 && trees[1] == trees[0]) continue;
    dofs += end - first;
  }
  if (dofs == 0) return 0;
  // its largest eigenvalue (its others are not needed, nor its vectors),
  // from the smaller of the two Gram matrices of those columns S: S S^T
  // (n x n) and S^T S (dofs x dofs) have the same nonzero eigenvalues (a
  // cube's four corners: 6 x 6 rather than 12 x 12, an eighth of the
  // solve's work)
  if (dofs < n) {
    w.columns.resize(n, dofs);
    int column = 0;
    for (int t = 0; t < 2; ++t) {
      const auto [first, end] = trees[t];
      if (first == end || (t == 1 && trees[1] == trees[0])) continue;
      w.columns.middleCols(column, end - first) = w.solved.middleCols(first, end - first);
      column += end - first;
    }
    w.product.noalias() = w.columns.transpose() * w.columns;
  } else {
    w.product.setZero(n, n);
    for (int t = 0; t < 2; ++t) {
      const auto [first, end] = trees[t];
      if (first == end || (t == 1 && trees[1] == trees[0])) continue;
      const auto block = w.solved.middleCols(first, end - first);
      w.product.noalias() += block * block.transpose();
    }
  }
  w.solver.compute(w.product, Eigen::EigenvaluesOnly);
  return std::max(w.solver.eigenvalues().maxCoeff(), 0.0);
}

double DamperRate::Bound(const mjModel* m, mjData* d, const GeomPair& pair, int points,
                         const mjtNum* pos, const mjtNum* normal, const double* damping,
                         DamperDirection direction) {
  const int nv = m->nv;
  const int per_point = direction == DamperDirection::kNormal ? 1 : 2;
  const int k = per_point * points;
  if (nv == 0 || k == 0) return 0;
  Workspace& w = *w_;
  w.forces.resize(static_cast<size_t>(k) * nv);
  w.halves.resize(static_cast<size_t>(k) * nv);
  for (int j = 0; j < points; ++j) {
    // the directions the dampers resist: the normal, or two tangents
    mjtNum directions[6];
    if (per_point == 1) {
      mju_copy3(directions, normal + 3 * j);
    } else {
      Tangents(normal + 3 * j, directions);
    }
    const double scale = std::sqrt(std::max(damping[j], 0.0));
    for (int a = 0; a < per_point; ++a) {
      mjtNum* row = w.forces.data() + static_cast<size_t>(per_point * j + a) * nv;
      NormalJacobian(m, d, pair, pos + 3 * j, directions + 3 * a, row);
      for (int i = 0; i < nv; ++i) row[i] *= scale;
    }
  }
  // the k x k matrix halves halves^T over the two bodies' trees' dofs (as
  // Rate), its squared entries and its trace
  mj_solveM2(m, d, w.halves.data(), w.forces.data(), k);
  std::pair<int, int> trees[2] = {TreeDofs(m, pair.body[0]), TreeDofs(m, pair.body[1])};
  if (trees[1] == trees[0]) trees[1] = {0, 0};
  double squares = 0, trace = 0;
  for (int a = 0; a < k; ++a) {
    const mjtNum* row_a = w.halves.data() + static_cast<size_t>(a) * nv;
    for (int b = a; b < k; ++b) {
      const mjtNum* row_b = w.halves.data() + static_cast<size_t>(b) * nv;
      double entry = 0;
      for (const auto& [first, end] : trees) {
        for (int i = first; i < end; ++i) entry += row_a[i] * row_b[i];
      }
      squares += (a == b ? 1 : 2) * entry * entry;
      if (a == b) trace += entry;
    }
  }
  return std::sqrt(squares) + kBoundMargin * trace;
}

}  // namespace contactlaws::internal
