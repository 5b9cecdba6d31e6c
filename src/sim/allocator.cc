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
// Base pages are 4 kB on x86-64 and arm64 (Linux's defaults) ...
constexpr size_t kPage = size_t{4} << 10;
// ... and transparent huge pages 2 MB.
constexpr size_t kHugePage = size_t{2} << 20;
// Blocks from this size on are mapped with their pages in place: below it, a
// block shares pages with others on the heap, and mapping it whole would
// cost a system call for a page fault or two.
constexpr size_t kMappedFrom = size_t{16} << 10;
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

enum class Source { kHeap, kMapped };

// In front of every block: what Free must give back, and how.
struct alignas(kMujocoAlignment) Header {
  void* base;
  size_t length;
  Source source;
};
static_assert(sizeof(Header) == kMujocoAlignment, "a block starts 64-byte aligned");

size_t RoundUp(size_t size, size_t to) { return (size + to - 1) / to * to; }

void* Place(void* base, size_t length, Source source) {
  if (!base) return nullptr;  // MuJoCo reports the failed allocation
  Header* header = static_cast<Header*>(base);
  *header = Header{base, length, source};
  return header + 1;
}

void* Allocate(size_t size) {
  const size_t total = size + sizeof(Header);
  if (total >= kMappedFrom && total < kHugeFrom) {
    const size_t length = RoundUp(total, kPage);
    void* base = mmap(nullptr, length, PROT_READ | PROT_WRITE,
                      MAP_PRIVATE | MAP_ANONYMOUS | MAP_POPULATE, -1, 0);
    return Place(base == MAP_FAILED ? nullptr : base, length, Source::kMapped);
  }
  if (total >= kHugeFrom && total < kHugeUpTo) {
    const size_t length = RoundUp(total, kHugePage);
    void* base = std::aligned_alloc(kHugePage, length);
    if (base) madvise(base, length, MADV_HUGEPAGE);  // advice: ignored where unsupported
    return Place(base, length, Source::kHeap);
  }
  const size_t length = RoundUp(total, kMujocoAlignment);
  return Place(std::aligned_alloc(kMujocoAlignment, length), length, Source::kHeap);
}

void Free(void* p) {
  if (!p) return;
  const Header* header = static_cast<Header*>(p) - 1;
  if (header->source == Source::kMapped) {
    munmap(header->base, header->length);
  } else {
    std::free(header->base);
  }
}

}  // namespace

void InstallMujocoAllocator() {
  mju_user_malloc = Allocate;
  mju_user_free = Free;
}

}  // namespace contactlaws
