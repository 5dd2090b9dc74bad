// --cluster-bench N: the cost of cluster mode alone. Every rank runs N frames
// of the configured scene's packets with no walls and no GL: rank 0's main
// context makes each packet and broadcasts it, every rank takes it and joins
// the swap barrier. --cluster-stats' summary then shows the bytes per frame
// and the time in the broadcast and the barrier, undisturbed by rendering.
#pragma once

#include <filesystem>

#include "app/cluster/mpi_cluster.h"
#include "core/config/app_config.h"

namespace sandstorm {

int runClusterBench(MpiCluster& cluster, const AppConfig& config, int frames);

}  // namespace sandstorm
