// Cluster mode's entry point: `mpirun -np K sandstorm --config FILE ...`
// (or --cluster). Every rank loads the same configuration; rank 0 checks that
// they agree and that every wall's rank exists, then each rank runs App with
// its share of the walls. Returns the process exit status: 0, 1 for a
// failure every rank agreed on (rank 0 said why); a rank that dies or hangs
// ends the job through MPI_Abort (MpiSession::kAbortStatus).
#pragma once

#include <filesystem>

#include "app/app.h"
#include "app/cluster/cluster_link.h"

namespace sandstorm {

// True when this process was started by mpirun (its environment says so).
bool launchedByMpirun();

int runCluster(const std::filesystem::path& configPath, const AppOptions& options,
               const ClusterOptions& cluster);

}  // namespace sandstorm
