// Copyright contactlaws authors.
//
// The one pool of threads of the library and its front-ends: independent
// items (runs of a sweep, trajectories of a replay) spread over threads,
// each thread with state of its own (a Simulation it reuses). Results go to
// each item's own place, so they do not depend on the number of threads.
// Items are coarse (a whole run): a thread per worker, started per call.

#ifndef CONTACTLAWS_SIM_PARALLEL_H_
#define CONTACTLAWS_SIM_PARALLEL_H_

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace contactlaws::internal {

// Calls work(worker, k) once for every k in [0, count), the items handed out
// in the order k = 0, 1, ... to min(jobs, count) workers (at least one);
// worker is in [0, workers) and names the thread, worker 0 being the calling
// thread. Once a call of work throws, no item starts; the first exception
// thrown is rethrown here when every worker has finished.
inline void ParallelFor(int count, int jobs, const std::function<void(int, int)>& work) {
  const int workers = std::max(1, std::min(jobs, count));
  std::atomic<int> next{0};
  std::mutex mutex;
  std::exception_ptr failure;
  auto run = [&](int worker) {
    for (int k = next++; k < count; k = next++) {
      try {
        work(worker, k);
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!failure) failure = std::current_exception();
        next = count;
      }
    }
  };
  std::vector<std::thread> threads;
  for (int worker = 1; worker < workers; ++worker) threads.emplace_back(run, worker);
  run(0);
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace contactlaws::internal

#endif  // CONTACTLAWS_SIM_PARALLEL_H_
