// Copyright contactlaws authors.
//
// cluster.h with MPI. Items go to ranks in turn (k mod ranks): the
// trajectories of a data file come in no order of cost, so each rank's share
// is a sample of the whole (docs/cluster.md measures the balance). Results
// are exchanged by two allgathers, so every rank holds every result and the
// reductions that follow run in item order on each: the same bits whatever
// the ranks.

#include <mpi.h>

#include <cstdint>
#include <cstdio>
#include <cstring>

#include "cli/cluster.h"

namespace contactlaws::cli {
namespace {

int Rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int Size() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

class MpiSpread final : public WorkSpread {
 public:
  bool Mine(int k, int) const override { return k % Size() == Rank(); }

  void Share(std::vector<std::string>* items) const override {
    const int count = static_cast<int>(items->size());
    // this rank's items: [length][bytes], in item order
    std::string mine;
    for (int k = 0; k < count; ++k) {
      if (!Mine(k, count)) continue;
      const uint64_t length = (*items)[k].size();
      mine.append(reinterpret_cast<const char*>(&length), sizeof length);
      mine += (*items)[k];
    }
    const int size = Size();
    std::vector<int> lengths(size), offsets(size);
    int length = static_cast<int>(mine.size());
    MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD);
    int total = 0;
    for (int r = 0; r < size; ++r) offsets[r] = total, total += lengths[r];
    std::string all(total, '\0');
    MPI_Allgatherv(mine.data(), length, MPI_BYTE, all.data(), lengths.data(), offsets.data(),
                   MPI_BYTE, MPI_COMM_WORLD);
    // rank r's items are k = r, r + size, ...
    for (int r = 0; r < size; ++r) {
      const char* at = all.data() + offsets[r];
      for (int k = r; k < count; k += size) {
        uint64_t n;
        std::memcpy(&n, at, sizeof n);
        (*items)[k].assign(at + sizeof n, n);
        at += sizeof n + n;
      }
    }
  }
};

bool joined = false;

}  // namespace

bool JoinCluster(int* argc, char*** argv) {
  // launched alone: the only process, without MPI's start-up
  if (!LauncherRankVariable()) return true;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  joined = true;
  if (Rank() != 0) std::freopen("/dev/null", "w", stdout);
  return true;
}

void LeaveCluster(int exit_code) {
  if (!joined) return;
  if (exit_code != 0 && Size() > 1) {
    // the others may wait in an exchange this rank will never join
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, exit_code);
  }
  MPI_Finalize();
}

const WorkSpread* ClusterSpread() {
  static const MpiSpread spread;
  return joined && Size() > 1 ? &spread : nullptr;
}

bool WritesOutputs() { return !joined || Rank() == 0; }

}  // namespace contactlaws::cli
