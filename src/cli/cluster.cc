// Copyright contactlaws authors.
//
// cluster.h without MPI: the only process. A launch by mpirun or srun (its
// rank in the environment) is refused rather than run N times over.

#include <fmt/format.h>

#include "cli/cluster.h"

namespace contactlaws::cli {

bool JoinCluster() {
  if (const char* rank = LauncherRankVariable()) {
    fmt::print(stderr,
               "contactlaws: launched by mpirun ({} is set) but built without MPI: "
               "rebuild with -DCONTACTLAWS_MPI=ON (docs/cluster.md)\n", rank);
    return false;
  }
  return true;
}

void SetThreadsPerRank(int) {}

void LeaveCluster(int) {}

WorkSpread* ClusterSpread() { return nullptr; }

bool WritesOutputs() { return true; }

}  // namespace contactlaws::cli
