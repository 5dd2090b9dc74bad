// BenchView: one view of sandstorm-bench, drawn as ViewRenderer draws it (the
// scene, the particles, the lit composite) with each stage timed on its own
// GpuStopwatch.
#pragma once

#include <glm/glm.hpp>

#include "contexts/bench/gpu_stopwatch.h"
#include "contexts/gl/objects.h"
#include "contexts/render/view_targets.h"
#include "contexts/scene/scene_renderer.h"
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
  BenchView();
  SceneRenderer& scene() { return scene_; }
  void render(const ParticleSystem& particles, const View& view, glm::ivec2 size,
              std::uint32_t destination, StageWatches& watches);

 private:
  SceneRenderer scene_;
  ViewTargets targets_;
  gl::Buffer viewBlock_, renderBlock_;
};

}  // namespace sandstorm::bench
