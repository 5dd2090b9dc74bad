#include "app/cluster/cluster_main.h"

#include <optional>

#include "app/cluster/cluster_bench.h"
#include "app/cluster/config_fingerprint.h"
#include "app/cluster/mpi_cluster.h"
#include "core/config/config_sets.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

bool launchedByMpirun() {
  return MpiSession::launchedByMpirun();
}

int runCluster(const std::filesystem::path& configPath, const AppOptions& options,
               const ClusterOptions& clusterOptions) {
  std::optional<MpiSession> mpi;
  try {
    mpi.emplace();
  } catch (const Error& e) {
    log::error("cluster mode: ", e.what());
    return 1;
  }
  // Every line this rank logs says which rank it came from.
  log::setTag(concat("rank ", mpi->rank()));
  MpiCluster cluster(*mpi, clusterOptions);

  std::optional<App> app;
  std::string fingerprint, error;
  try {
    AppConfig config = loadConfig(configPath);
    applyConfigSets(config, options.sets);
    fingerprint = configFingerprint(config, options);
    app.emplace(std::move(config), options, &cluster);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!cluster.start(app ? &app->config() : nullptr, fingerprint, error)) return 1;
  if (clusterOptions.benchFrames > 0)
    return runClusterBench(cluster, app->config(), clusterOptions.benchFrames);
  try {
    return app->run();
  } catch (const std::exception& e) {
    cluster.fail(e.what());  // says it: to every rank before the first frame, or by aborting
    return 1;
  }
}

}  // namespace sandstorm
