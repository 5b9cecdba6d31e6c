// Copyright contactlaws authors.

#include "sim/allocator.h"

#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>

#include <mujoco/mujoco.h>

namespace contactlaws {
namespace {

// MuJoCo 2.2.2's own allocator aligns to 64 bytes (engine_util_errmem.c).
constexpr size_t kMujocoAlignment = 64;
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

void InstallMujocoAllocator() {
  mju_user_malloc = Allocate;
  mju_user_free = Free;
}

}  // namespace contactlaws
