// Copyright contactlaws authors.
//
// Independent runs on several threads, their results delivered in order on
// the calling thread: what makes a sweep on N threads write the same bytes
// as on one.

#ifndef CONTACTLAWS_APP_PARALLEL_H_
#define CONTACTLAWS_APP_PARALLEL_H_

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "sim/parallel.h"

namespace contactlaws::app {

// Calls work(k) for k = 0 .. count-1 on up to `jobs` threads of the pool
// (internal::ParallelFor; jobs <= 1: on this thread, one after the other),
// and deliver(k, result) on this thread in the order k = 0, 1, ... as soon
// as result k and every result before it are ready, so that output written
// by deliver does not depend on jobs. Once
// should_stop() is true, the works not yet started are skipped: skipped(k)
// stands for their result. An exception thrown by work(k) is rethrown here
// when k's turn to be delivered comes, after the running works have finished.
template <typename Result>
void RunInOrder(int count, int jobs, const std::function<Result(int)>& work,
                const std::function<void(int, Result&)>& deliver,
                const std::function<bool()>& should_stop,
                const std::function<Result(int)>& skipped) {
  if (jobs <= 1 || count <= 1) {
    for (int k = 0; k < count; ++k) {
      Result r = should_stop() ? skipped(k) : work(k);
      deliver(k, r);
    }
    return;
  }
  struct Slot {
    std::optional<Result> result;
    std::exception_ptr error;
    bool done = false;
  };
  std::vector<Slot> slots(count);
  std::mutex mutex;
  std::condition_variable ready;
  std::atomic<bool> abandoned{false};  // a delivery failed: start nothing more

  // the works on the one pool (internal::ParallelFor), run beside this
  // thread, which delivers
  std::thread pool([&] {
    internal::ParallelFor(count, jobs, [&](int, int k) {
      std::optional<Result> r;
      std::exception_ptr error;
      if (!abandoned) {
        try {
          r.emplace(should_stop() ? skipped(k) : work(k));
        } catch (...) {
          error = std::current_exception();
        }
      }
      {
        std::lock_guard lock(mutex);
        slots[k].result = std::move(r);
        slots[k].error = error;
        slots[k].done = true;
      }
      ready.notify_all();
    });
  });

  std::exception_ptr failure;
  for (int k = 0; k < count && !failure; ++k) {
    {
      std::unique_lock lock(mutex);
      ready.wait(lock, [&] { return slots[k].done; });
    }
    try {
      if (slots[k].error) std::rethrow_exception(slots[k].error);
      deliver(k, *slots[k].result);
      slots[k].result.reset();  // a delivered run's buffers are freed at once
    } catch (...) {
      failure = std::current_exception();
      abandoned = true;
    }
  }
  pool.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace contactlaws::app

#endif  // CONTACTLAWS_APP_PARALLEL_H_
