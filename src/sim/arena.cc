// Copyright contactlaws authors.

#include "sim/arena.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstdlib>

#include "contactlaws/contact_data.h"

namespace contactlaws {
namespace {

// MuJoCo 2.2.2's compiler (user_model.cc): njmax when the scene gives none.
constexpr int kMujocoDefaultNjmax = 500;

// MuJoCo 2.2.2's compiler's nstack when the scene gives none, for njmax rows:
// max(1000, 5 (njmax + neq + nv)^2 + 20 (sizes)).
long MujocoStackHeuristic(const mjModel* m, long njmax) {
  const long rows = njmax + m->neq + m->nv;
  const long sizes = m->nq + m->nv + m->nu + m->na + m->nbody + m->njnt + m->ngeom + m->nsite +
                     m->neq + m->ntendon + m->nwrap;
  return std::max(1000L, 5 * rows * rows + 20 * sizes);
}

// mjtNum the passive hook takes from the stack per evaluation: two 3 x nv
// Jacobians and two nv vectors (src/mujoco/kinematics.cc), with the energy
// ledger's nv (Simulation::Energy) and room for a second pair.
long HookStack(const mjModel* m) { return 2 * (8 * static_cast<long>(m->nv) + m->nv); }

// Rows of a connect, weld, joint, tendon or distance equality: at most 6.
constexpr int kMaxEqualityRows = 6;

// The constraint rows a scene without contact constraints can make: its
// equalities, friction losses and limits (one row each).
long RowsWithoutContacts(const mjModel* m) {
  long rows = kMaxEqualityRows * static_cast<long>(m->neq);
  for (int v = 0; v < m->nv; ++v) rows += m->dof_frictionloss[v] > 0;
  for (int j = 0; j < m->njnt; ++j) rows += m->jnt_limited[j] != 0;
  for (int t = 0; t < m->ntendon; ++t) {
    rows += (m->tendon_frictionloss[t] > 0) + (m->tendon_limited[t] != 0);
  }
  return rows;
}

// Transparent huge pages are 2 MB on x86-64 and arm64 (4 kB base pages).
constexpr size_t kHugePage = size_t{2} << 20;
// Blocks from this size on go on huge pages (below it, the rounding up to
// 2 MB would cost more than the faults it saves) ...
constexpr size_t kHugeFrom = size_t{1} << 20;
// ... up to this size: what MuJoCo zeroes whole when it makes an mjData, the
// compiler's 3.2 MB buffer for its default njmax of 500, gains; the stack
// (nstack x 8 bytes, 10 MB for njmax 500) is touched only at its start, and
// a 2 MB page would zero 2 MB at its first use (measured: the run without
// the model cache 3.75 ms of CPU with a stack on 4 kB pages against 4.06 ms
// on huge pages, scripts/startup_bench.sh). A size alone tells the two
// apart only for MuJoCo's defaults; anything else gets 4 kB pages, which
// is MuJoCo's own behaviour.
constexpr size_t kHugeUpTo = size_t{8} << 20;
// MuJoCo 2.2.2's own allocator aligns to 64 bytes (engine_util_errmem.c).
constexpr size_t kMujocoAlignment = 64;

size_t RoundUp(size_t size, size_t to) { return (size + to - 1) / to * to; }

void* Allocate(size_t size) {
  if (size >= kHugeFrom && size < kHugeUpTo) {
    const size_t rounded = RoundUp(size, kHugePage);
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (p) madvise(p, rounded, MADV_HUGEPAGE);  // advice: ignored where unsupported
    return p;
  }
  return std::aligned_alloc(kMujocoAlignment, RoundUp(size, kMujocoAlignment));
}

void Free(void* p) { std::free(p); }

}  // namespace

void UseHugePagesForLargeAllocations() {
  mju_user_malloc = Allocate;
  mju_user_free = Free;
}

bool HasUntaggedContacts(const ContactModel& cm) {
  const mjModel* m = cm.model();
  if (m->npair > 0) return true;
  for (int g1 = 0; g1 < m->ngeom; ++g1) {
    for (int g2 = g1 + 1; g2 < m->ngeom; ++g2) {
      if (!DefaultContactFilter(m, g1, g2) && cm.FindPair(g1, g2) < 0) return true;
    }
  }
  return false;
}

void SizeArena(mjModel* m, const ContactModel& cm) {
  const bool defaults = m->njmax == kMujocoDefaultNjmax &&
                        m->nstack == MujocoStackHeuristic(m, kMujocoDefaultNjmax);
  if (!defaults || HasUntaggedContacts(cm)) return;
  m->njmax = static_cast<int>(RowsWithoutContacts(m));
  m->nstack = static_cast<int>(MujocoStackHeuristic(m, m->njmax) + HookStack(m));
}

}  // namespace contactlaws
