// Copyright contactlaws authors.
//
// The program's place in a cluster job. Built with MPI (CONTACTLAWS_MPI),
// the program launched by mpirun or srun is one rank of the job: the ranks
// share the trajectories of replay and fit and the runs of compare and
// restitution (ClusterSpread), and rank 0 alone writes. Built without it, or
// launched alone, it is the only process.

#ifndef CONTACTLAWS_CLI_CLUSTER_H_
#define CONTACTLAWS_CLI_CLUSTER_H_

#include "ident/work_spread.h"

#include <cstdlib>

namespace contactlaws::cli {

// The variable by which mpirun or srun gives a process its rank, when set
// (the program was launched as a rank of a job); null otherwise.
inline const char* LauncherRankVariable() {
  for (const char* rank : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"}) {
    if (std::getenv(rank)) return rank;
  }
  return nullptr;
}

// Joins the job (MPI_Init, on a thread of its own: the command goes on
// meanwhile) and, on ranks other than 0, sends standard output to /dev/null.
// Returns false, having printed one line, when the program was launched by
// mpirun but built without MPI.
bool JoinCluster();
// The threads each rank runs (--jobs), for the timing line.
void SetThreadsPerRank(int jobs);
// Leaves the job (MPI_Finalize) once every rank leaves. An exit_code other
// than 0, kExitIncomplete and kExitInterrupted (which every rank reaches
// alike) ends every rank at once.
// After a command that spread its work, rank 0 prints the timing line on
// stderr (docs/cluster.md).
void LeaveCluster(int exit_code);

// The spread over the job's ranks; null when the program is the only process.
WorkSpread* ClusterSpread();
// Whether this process writes the outputs (rank 0, or the only process).
bool WritesOutputs();

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_CLUSTER_H_
