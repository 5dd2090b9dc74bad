#include "app/cluster/cluster_bench.h"

#include <chrono>

#include "app/app.h"
#include "app/scene_setup.h"
#include "core/sim/main_context.h"
#include "core/util/log.h"

namespace sandstorm {

int runClusterBench(MpiCluster& cluster, const AppConfig& config, int frames) {
  AppConfig bare = config;
  AppOptions options;
  bare.walls.clear();  // no walls: nothing to wait for but the other ranks
  cluster.localize(bare, options);
  FieldSource field;
  std::string error;
  try {
    if (cluster.makesField()) field = makeField(config.field, config.folder);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!cluster.ready(error)) return 1;
  cluster.shareField(field);

  MainContext::Options mainOptions;
  mainOptions.seed = config.run.seed;
  mainOptions.fixedDt = config.run.fixedDt > 0.0f ? config.run.fixedDt : 1.0f / 60.0f;
  mainOptions.capacityLimit = config.run.capacityLimit;
  MainContext main(config.particles, field.update, mainOptions);
  if (field.timeline) useField(main, field);
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) {
    if (cluster.root())
      cluster.send(main.next());
    else if (!cluster.receive())
      break;
    if (!cluster.swap(std::uint32_t(f), 0, {}).go) return 1;
  }
  if (cluster.root())
    cluster.sendStop();
  else
    cluster.receive();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (cluster.root())
    log::info("cluster bench: ", frames, " frames in ", seconds,
              " s: ", 1e3 * seconds / std::max(frames, 1),
              " ms per frame of broadcast + swap barrier");
  cluster.finish();
  return 0;
}

}  // namespace sandstorm
