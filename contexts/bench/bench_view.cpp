#include "contexts/bench/bench_view.h"

#include <epoxy/gl.h>

#include "contexts/particles/particle_system.h"
#include "contexts/render/frame_blocks.h"

namespace sandstorm::bench {

BenchView::BenchView() : viewBlock_(gl::createBuffer()), renderBlock_(gl::createBuffer()) {
  glNamedBufferStorage(viewBlock_.id(), sizeof(ViewBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(renderBlock_.id(), sizeof(RenderBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void BenchView::render(const ParticleSystem& particles, const View& view, glm::ivec2 size,
                       std::uint32_t destination, StageWatches& watches) {
  targets_.resize(size);
  const ViewBlock vb = makeViewBlock(view, size);
  const RenderBlock rb = makeRenderBlock(particles.state().render);
  glNamedBufferSubData(viewBlock_.id(), 0, sizeof(vb), &vb);
  glNamedBufferSubData(renderBlock_.id(), 0, sizeof(rb), &rb);
  glBindBufferBase(GL_UNIFORM_BUFFER, 1, viewBlock_.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, 2, renderBlock_.id());

  watches.scene.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.sceneFramebuffer());
  glViewport(0, 0, size.x, size.y);
  glDepthMask(GL_TRUE);
  const float depth = 1.0f;
  glClearNamedFramebufferfv(targets_.sceneFramebuffer(), GL_DEPTH, 0, &depth);
  if (const auto field = particles.field();
      field && field->field && particles.state().render.fieldBox)
    scene_.setFieldBox(field->field->bounds(), field->placement);
  else
    scene_.setFieldBox(std::nullopt, {});
  scene_.draw();
  watches.scene.end();

  watches.particles.begin();
  particles.renderParticles(targets_, &view);
  watches.particles.end();
  watches.post.begin();
  particles.composite(targets_, destination, {0, 0});
  watches.post.end();
}

}  // namespace sandstorm::bench
