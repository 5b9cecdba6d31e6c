// Copyright contactlaws authors.
//
// Work items spread over processes (the ranks of a cluster job): which items
// this process computes, and the exchange that gives every process every
// item's result, in item order. The library knows only this interface; the
// program chooses the transport (MPI in src/cli/cluster_mpi.cc). Inside a
// process, items are still spread over threads (ReplayOptions::jobs).

#ifndef CONTACTLAWS_WORK_SPREAD_H_
#define CONTACTLAWS_WORK_SPREAD_H_

#include <string>
#include <vector>

namespace contactlaws {

class WorkSpread {
 public:
  virtual ~WorkSpread() = default;
  // Whether this process computes item k of count.
  virtual bool Mine(int k, int count) const = 0;
  // items has one entry per item; this process's entries hold its results
  // (opaque bytes). Returns with every entry filled from the process that
  // computed it, on every process. Every process calls it with the same
  // count, in the same order of calls.
  virtual void Share(std::vector<std::string>* items) const = 0;
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_WORK_SPREAD_H_
