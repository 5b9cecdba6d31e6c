// Copyright contactlaws authors.
//
// Work items spread over processes (the ranks of a cluster job): which items
// this process computes, and the exchange that gives every process every
// item's result, in item order. The library knows only this interface; the
// program chooses the transport (MPI in src/cli/cluster_mpi.cc). Inside a
// process, items are still spread over threads (ReplayOptions::jobs).

#ifndef CONTACTLAWS_IDENT_WORK_SPREAD_H_
#define CONTACTLAWS_IDENT_WORK_SPREAD_H_

#include <time.h>

#include <string>
#include <vector>

namespace contactlaws {
namespace internal {

// Declared in replay.h (ReplayOptions::spread), implemented by the program.
class WorkSpread {
 public:
  virtual ~WorkSpread() = default;
  // The expected cost of each item of the next spread of cost.size() items
  // (any unit, the same on every process), known before any is computed:
  // a first spread hands the items out by it, longest first, rather than in
  // turn. The seconds of an earlier Share of the same count take precedence.
  virtual void Expect(const std::vector<double>& cost) = 0;
  // Whether this process computes item k of count.
  virtual bool Mine(int k, int count) const = 0;
  // items and seconds have one entry per item; this process's entries hold
  // its results (opaque bytes) and the seconds each took to compute
  // (ThreadSeconds). Returns
  // with every entry of items filled from the process that computed it, on
  // every process. Every process calls it with the same count, in the same
  // order of calls. The seconds decide who computes what in the next call
  // with the same count (the costs of one evaluation foretell the next's).
  virtual void Share(std::vector<std::string>* items, const std::vector<double>& seconds) = 0;
};

// Each of seconds.size() items' process (0 .. processes - 1): longest first,
// to the process with the least seconds so far (the lowest on a tie), within
// 4/3 of the best balance (Graham's bound for longest-processing-time-first).
// Every process computes the same plan from the same costs: no message
// decides it.
std::vector<int> LongestFirst(const std::vector<double>& seconds, int processes);

// The CPU time of the calling thread, s: an item's cost for Share, which on a
// machine shared with other work its wall time would overstate.
inline double ThreadSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace internal

// The names the program's own code (the ranks of src/cli/cluster*) uses.
using internal::LongestFirst;
using internal::ThreadSeconds;
using internal::WorkSpread;

}  // namespace contactlaws

#endif  // CONTACTLAWS_IDENT_WORK_SPREAD_H_
