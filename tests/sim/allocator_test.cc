// Copyright contactlaws authors.
//
// The command line's allocator for MuJoCo (sim/allocator.h): every class of
// block aligned as MuJoCo's own, whole and given back; a run on it the same,
// bit for bit, as on MuJoCo's own allocator.

#include "sim/allocator.h"

#include <cstdint>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "contactlaws/contactlaws.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

// Installs the allocator for one scope: every MuJoCo block of the test is
// made and freed inside it, then MuJoCo's own allocator is back.
class Installed {
 public:
  Installed() { InstallMujocoAllocator(); }
  ~Installed() {
    mju_user_malloc = nullptr;
    mju_user_free = nullptr;
  }
  Installed(const Installed&) = delete;
  Installed& operator=(const Installed&) = delete;
};

// MuJoCo 2.2.2's own alignment.
constexpr uintptr_t kAlignment = 64;

TEST(AllocatorTest, EveryClassOfBlockIsAlignedWholeAndGivenBack) {
  Installed installed;
  // small, just under, at and past the huge pages' class, and beyond it
  for (const size_t size : {size_t{1}, size_t{100}, size_t{100} << 10, (size_t{1} << 20) - 1,
                            size_t{1} << 20, size_t{3} << 20, (size_t{8} << 20) - 1,
                            size_t{9} << 20}) {
    auto* p = static_cast<unsigned char*>(mju_malloc(size));
    ASSERT_NE(p, nullptr) << size;
    EXPECT_EQ(reinterpret_cast<uintptr_t>(p) % kAlignment, 0u) << size;
    std::memset(p, 0xab, size);  // the whole block is the caller's
    EXPECT_EQ(p[0], 0xab);
    EXPECT_EQ(p[size - 1], 0xab);
    mju_free(p);
  }
  mju_free(nullptr);  // as free(): nothing
}

// The state after n steps of the resting cube, made and run under whichever
// allocator is installed.
std::vector<double> CubeAfter(int n) {
  Simulation sim(LoadModelString(testing::CubeOnFloorXml(1e-4, 0.0499, "law=hunt-crossley restitution=0.5"),
                                 "cube.xml"),
                 "cube.xml");
  for (int i = 0; i < n; ++i) sim.Step();
  const mjData* d = sim.data();
  std::vector<double> state(d->qpos, d->qpos + sim.model()->nq);
  state.insert(state.end(), d->qvel, d->qvel + sim.model()->nv);
  return state;
}

TEST(AllocatorTest, ARunOnItIsTheRunOnMujocosOwn) {
  constexpr int kSteps = 200;
  const std::vector<double> own = CubeAfter(kSteps);
  std::vector<double> ours;
  {
    Installed installed;
    ours = CubeAfter(kSteps);
  }
  ASSERT_EQ(ours.size(), own.size());
  for (size_t i = 0; i < own.size(); ++i) EXPECT_EQ(ours[i], own[i]) << i;  // bit for bit
  EXPECT_LT(own[2], 0.05);  // the cube moved: it was pressed into the floor
}

}  // namespace
}  // namespace contactlaws
