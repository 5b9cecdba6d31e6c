// Copyright contactlaws authors.
//
// MuJoCo's allocations for a program that loads a scene, makes its data and
// exits soon after (the command line): each block by its size, so that
// making an mjData faults as few pages as it can.

#ifndef CONTACTLAWS_SIM_ALLOCATOR_H_
#define CONTACTLAWS_SIM_ALLOCATOR_H_

namespace contactlaws {

// Sets mju_user_malloc and mju_user_free: call once, before any MuJoCo
// allocation (a block MuJoCo's own allocator made must not reach ours).
//   - from 1 MB to 8 MB (the compiler's own mjData buffer, sized by MuJoCo's
//     defaults and zeroed whole): on transparent huge pages (madvise), so
//     that zeroing it faults a few 2 MB pages rather than hundreds of 4 kB
//     ones;
//   - the others (the compiler's 10 MB stack among them, barely touched) as
//     MuJoCo's own allocator does: from the heap.
// Every block is 64-byte aligned, as MuJoCo's own.
void InstallMujocoAllocator();

}  // namespace contactlaws

#endif  // CONTACTLAWS_SIM_ALLOCATOR_H_
