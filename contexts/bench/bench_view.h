// BenchView: one view of sandstorm-bench, drawn by the app's own ViewRenderer
// (the scene, the particles, the lit composite) with each stage timed on its
// own GpuStopwatch.
#pragma once

#include <glm/glm.hpp>

#include "contexts/bench/gpu_stopwatch.h"
#include "contexts/render/view_renderer.h"
#include "core/cave/view.h"

namespace sandstorm {
class ParticleSystem;
}

namespace sandstorm::bench {

struct StageWatches {
  GpuStopwatch scene, particles, post;
};

class BenchView {
 public:
  SceneRenderer& scene() { return renderer_.scene(); }
  void render(const ParticleSystem& particles, const View& view, glm::ivec2 size,
              std::uint32_t destination, StageWatches& watches);

 private:
  ViewRenderer renderer_;
};

}  // namespace sandstorm::bench
