#include "contexts/bench/bench_view.h"

#include "contexts/particles/particle_system.h"

namespace sandstorm::bench {

void BenchView::render(const ParticleSystem& particles, const View& view, glm::ivec2 size,
                       std::uint32_t destination, StageWatches& watches) {
  watches.scene.begin();
  renderer_.drawScene(particles, view, size);
  watches.scene.end();
  watches.particles.begin();
  particles.renderParticles(renderer_.targets(), &view);
  watches.particles.end();
  watches.post.begin();
  particles.composite(renderer_.targets(), destination, {0, 0});
  watches.post.end();
}

}  // namespace sandstorm::bench
