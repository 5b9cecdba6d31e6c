// Copyright contactlaws authors.
//
// The one pool (sim/parallel.h) and the application's ordered delivery on
// it (app/parallel.h): every item once, each worker on a thread of its own
// (worker 0 the caller's), a failure stopping what has not started, and the
// results delivered in order whatever the order they finish in.

#include "sim/parallel.h"

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "app/parallel.h"

namespace contactlaws {
namespace {

TEST(ParallelForTest, EveryItemOnceEachWorkerOnAThreadOfItsOwn) {
  constexpr int kCount = 40, kJobs = 3;
  std::vector<std::atomic<int>> calls(kCount);
  std::mutex mutex;
  std::map<int, std::set<std::thread::id>> threads_of;
  internal::ParallelFor(kCount, kJobs, [&](int worker, int k) {
    ++calls[k];
    // a little work, so that every worker takes some items
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    std::lock_guard lock(mutex);
    threads_of[worker].insert(std::this_thread::get_id());
  });
  for (int k = 0; k < kCount; ++k) EXPECT_EQ(calls[k], 1) << k;
  ASSERT_LE(threads_of.size(), static_cast<size_t>(kJobs));
  std::set<std::thread::id> all;
  for (const auto& [worker, ids] : threads_of) {
    EXPECT_GE(worker, 0);
    EXPECT_LT(worker, kJobs);
    EXPECT_EQ(ids.size(), 1u) << "worker " << worker << " ran on more than one thread";
    all.insert(*ids.begin());
  }
  EXPECT_EQ(all.size(), threads_of.size());  // no two workers share a thread
  EXPECT_EQ(*threads_of[0].begin(), std::this_thread::get_id());
}

TEST(ParallelForTest, AFailureStopsWhatHasNotStartedAndIsRethrown) {
  constexpr int kCount = 1000;
  std::atomic<int> started{0};
  // an item takes 1 ms: the other worker would need half a second to
  // start half of them before item 3's failure stops it
  EXPECT_THROW(internal::ParallelFor(kCount, 2,
                                     [&](int, int k) {
                                       ++started;
                                       if (k == 3) throw std::runtime_error("item 3");
                                       std::this_thread::sleep_for(std::chrono::milliseconds(1));
                                     }),
               std::runtime_error);
  EXPECT_LT(started, kCount / 2);
}

TEST(RunInOrderTest, DeliversInOrderWhateverTheOrderTheyFinishIn) {
  constexpr int kCount = 12;
  std::vector<int> delivered;
  app::RunInOrder<int>(
      kCount, 3,
      [](int k) {
        // the first items finish last
        std::this_thread::sleep_for(std::chrono::milliseconds(kCount - k));
        return 10 * k;
      },
      [&](int k, int& result) {
        EXPECT_EQ(result, 10 * k);
        delivered.push_back(k);
      },
      [] { return false; }, [](int) { return -1; });
  ASSERT_EQ(delivered.size(), static_cast<size_t>(kCount));
  for (int k = 0; k < kCount; ++k) EXPECT_EQ(delivered[k], k);
}

TEST(RunInOrderTest, AWorksFailureIsRethrownAtItsTurn) {
  std::vector<int> delivered;
  EXPECT_THROW(app::RunInOrder<int>(
                   6, 2,
                   [](int k) {
                     if (k == 2) throw std::runtime_error("run 2");
                     return k;
                   },
                   [&](int k, int&) { delivered.push_back(k); }, [] { return false; },
                   [](int) { return -1; }),
               std::runtime_error);
  EXPECT_EQ(delivered, (std::vector<int>{0, 1}));
}

}  // namespace
}  // namespace contactlaws
