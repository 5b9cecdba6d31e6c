// Copyright contactlaws authors.

#include "mujoco/damper_rate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "mujoco/kinematics.h"

namespace contactlaws::internal {

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
  // sqrt(c) (J1 - J0)^T u per point and direction u, and their halves
  // D^-1/2 L^-T of M^-1 (M = L^T D L), row by row (vectors: their capacity
  // stays); the two bodies' trees' dofs
  std::vector<mjtNum> forces, halves;
  std::vector<int> dofs;
  Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic> product;  // Rate's: its lower triangle
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic>> solver;
};

DamperRate::DamperRate() : w_(std::make_unique<Workspace>()) {}
DamperRate::~DamperRate() = default;

int DamperRate::Halves(const mjModel* m, mjData* d, const GeomPair& pair, int points,
                       const mjtNum* pos, const mjtNum* normal, const double* damping,
                       DamperDirection direction) {
  const int nv = m->nv;
  const int per_point = direction == DamperDirection::kNormal ? 1 : 2;
  const int k = per_point * points;
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
  mj_solveM2(m, d, w.halves.data(), w.forces.data(), k);
  // the two bodies' trees' dofs, each tree once: M is block diagonal over
  // the world's children, so the halves are 0 outside them (a ball among 64
  // free ones: 12 of 384 dofs)
  std::pair<int, int> trees[2] = {TreeDofs(m, pair.body[0]), TreeDofs(m, pair.body[1])};
  if (trees[1] == trees[0]) trees[1] = {0, 0};
  w.dofs.clear();
  for (const auto& [first, end] : trees) {
    for (int i = first; i < end; ++i) w.dofs.push_back(i);
  }
  return k;
}

double DamperRate::Rate(const mjModel* m, mjData* d, const GeomPair& pair, int points,
                        const mjtNum* pos, const mjtNum* normal, const double* damping,
                        DamperDirection direction) {
  const int nv = m->nv;
  if (nv == 0 || points == 0) return 0;
  // the halves S (k x dofs) of the rows sqrt(c) u^T (J1 - J0): the rate's
  // matrix C^(1/2) P J M^-1 J^T P C^(1/2) has the nonzero eigenvalues of
  // S S^T (P = t1 t1^T + t2 t2^T for two tangents t, or n n^T)
  const int k = Halves(m, d, pair, points, pos, normal, damping, direction);
  return LargestEigenvalue(k, nv);
}

double DamperRate::RateAfterBound(const mjModel* m) {
  return m->nv == 0 || rows_ == 0 ? 0.0 : LargestEigenvalue(rows_, m->nv);
}

double DamperRate::LargestEigenvalue(int k, int nv) {
  Workspace& w = *w_;
  const int dofs = static_cast<int>(w.dofs.size());
  if (dofs == 0) return 0;
  // its largest eigenvalue (its others are not needed, nor its vectors),
  // from the smaller of S's two Gram matrices, which have the same nonzero
  // eigenvalues: S S^T (k x k) or S^T S (dofs x dofs) (a cube's four
  // corners: 6 x 6 rather than 8 x 8; the solver's work grows as the cube
  // of the size). The solver reads the lower triangle.
  const mjtNum* halves = w.halves.data();
  if (dofs < k) {
    w.product.resize(dofs, dofs);
    for (int p = 0; p < dofs; ++p) {
      for (int q = p; q < dofs; ++q) {
        mjtNum sum = 0;
        for (int r = 0; r < k; ++r) {
          const mjtNum* row = halves + static_cast<size_t>(r) * nv;
          sum += row[w.dofs[p]] * row[w.dofs[q]];
        }
        w.product(q, p) = sum;
      }
    }
  } else {
    w.product.resize(k, k);
    for (int r = 0; r < k; ++r) {
      const mjtNum* row_r = halves + static_cast<size_t>(r) * nv;
      for (int s = r; s < k; ++s) {
        const mjtNum* row_s = halves + static_cast<size_t>(s) * nv;
        mjtNum sum = 0;
        for (const int i : w.dofs) sum += row_r[i] * row_s[i];
        w.product(s, r) = sum;
      }
    }
  }
  w.solver.compute(w.product, Eigen::EigenvaluesOnly);
  return std::max(w.solver.eigenvalues().maxCoeff(), 0.0);
}

double DamperRate::Bound(const mjModel* m, mjData* d, const GeomPair& pair, int points,
                         const mjtNum* pos, const mjtNum* normal, const double* damping,
                         DamperDirection direction) {
  const int nv = m->nv;
  rows_ = 0;
  if (nv == 0 || points == 0) return 0;
  const int k = Halves(m, d, pair, points, pos, normal, damping, direction);
  rows_ = k;
  Workspace& w = *w_;
  // the k x k matrix halves halves^T over the two bodies' trees' dofs (as
  // Rate), its squared entries and its trace
  double squares = 0, trace = 0;
  for (int a = 0; a < k; ++a) {
    const mjtNum* row_a = w.halves.data() + static_cast<size_t>(a) * nv;
    for (int b = a; b < k; ++b) {
      const mjtNum* row_b = w.halves.data() + static_cast<size_t>(b) * nv;
      double entry = 0;
      for (const int i : w.dofs) entry += row_a[i] * row_b[i];
      squares += (a == b ? 1 : 2) * entry * entry;
      if (a == b) trace += entry;
    }
  }
  return std::sqrt(squares) + kBoundMargin * trace;
}

double DamperRate::InertiaBound(const mjModel* m, const mjData* d, const GeomPair& pair,
                                int points, const mjtNum* pos, const double* damping,
                                DamperDirection direction) const {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const int per_point = direction == DamperDirection::kNormal ? 1 : 2;
  // each body's inverse mass and inverse smallest principal moment; a static
  // body takes no part
  double inverse_mass[2] = {0, 0}, inverse_moment[2] = {0, 0};
  for (int b = 0; b < 2; ++b) {
    const int body = pair.body[b];
    const std::pair<int, int> tree = TreeDofs(m, body);
    if (tree.first == tree.second) continue;
    if (!SingleFreeBody(m, body) || (b == 1 && pair.body[0] == body)) return kInfinity;
    const mjtNum* inertia = m->body_inertia + 3 * body;
    const double smallest = std::min({inertia[0], inertia[1], inertia[2]});
    if (!(m->body_mass[body] > 0 && smallest > 0)) return kInfinity;
    inverse_mass[b] = 1 / m->body_mass[body];
    inverse_moment[b] = 1 / smallest;
  }
  double trace = 0;
  for (int j = 0; j < points; ++j) {
    double inverse_inertia = 0;  // the point's, along any direction, at most
    for (int b = 0; b < 2; ++b) {
      if (inverse_mass[b] == 0) continue;
      mjtNum r[3];
      mju_sub3(r, pos + 3 * j, d->xipos + 3 * pair.body[b]);
      inverse_inertia += inverse_mass[b] + mju_dot3(r, r) * inverse_moment[b];
    }
    trace += per_point * std::max(damping[j], 0.0) * inverse_inertia;
  }
  return (1 + kBoundMargin) * trace;
}

}  // namespace contactlaws::internal
