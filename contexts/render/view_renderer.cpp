#include "contexts/render/view_renderer.h"

#include <epoxy/gl.h>

#include "contexts/particles/particle_system.h"
#include "contexts/render/frame_blocks.h"
#include "core/cave/window_segments.h"

namespace sandstorm {
namespace {

constexpr GLuint kSceneDepthUnit = 8;  // scene_occlusion.glsl

}  // namespace

ViewRenderer::ViewRenderer() : viewBlock_(gl::createBuffer()), renderBlock_(gl::createBuffer()) {
  glNamedBufferStorage(viewBlock_.id(), sizeof(ViewBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(renderBlock_.id(), sizeof(RenderBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void ViewRenderer::render(const ParticleSystem& particles, const View& view, glm::ivec2 size,
                          std::uint32_t destination, glm::ivec2 origin, gl::FrameStageTimer* timer,
                          const View* next) {
  using Stage = gl::FrameStageTimer::Stage;
  if (timer) timer->begin(Stage::Scene);
  drawScene(particles, view, size);
  if (timer) timer->end();
  if (timer) timer->begin(Stage::Particles);
  particles.renderParticles(targets_, &view, next);
  if (timer) timer->end();
  if (timer) timer->begin(Stage::Post);
  particles.composite(targets_, destination, origin);
  if (timer) timer->end();
}

void ViewRenderer::drawScene(const ParticleSystem& particles, const View& view, glm::ivec2 size) {
  targets_.resize(size);
  const ViewBlock vb = makeViewBlock(view, size);
  const auto field = particles.field();
  const RenderSettings& look = particles.state().render;
  const RenderBlock rb =
      makeRenderBlock(particles.state(), field.get(), particles.fieldBlend(),
                      colorTables_.get(look.colorMap, look.colorBirth, look.colorDeath));
  glNamedBufferSubData(viewBlock_.id(), 0, sizeof(vb), &vb);
  glNamedBufferSubData(renderBlock_.id(), 0, sizeof(rb), &rb);
  glBindBufferBase(GL_UNIFORM_BUFFER, 1, viewBlock_.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, 2, renderBlock_.id());
  scene_.bindColorGrid();     // texture units 5 and 6, for colouring by vorticity or an array
  particles.shadow().bind();  // uniform binding 4, texture unit 7: the dust's shadow

  if (field && field->field && particles.state().render.fieldBox)
    scene_.setFieldBox(field->field->bounds(), field->placement);
  else
    scene_.setFieldBox(std::nullopt, {});
  scene_.setHelicopter(particles.state().helicopter, HelicopterModel{}.rotorRadius);
  scene_.setObstacles(particles.state().obstacles);
  scene_.setPrimitives(particles.state().primitives);
  // Raster items (a height map's terrain, props, lines, the wand) first, into
  // the items' depth buffer; with none, the background alone draws the scene.
  const bool raster = scene_.rasterItems();
  glViewport(0, 0, size.x, size.y);
  if (raster) {
    glBindFramebuffer(GL_FRAMEBUFFER, targets_.sceneFramebuffer());
    glDepthMask(GL_TRUE);
    const float depth = 1.0f;
    glClearNamedFramebufferfv(targets_.sceneFramebuffer(), GL_DEPTH, 0, &depth);
    scene_.drawOpaque();
  }
  // The field's box: lines drawn by the background's compute pass.
  const std::vector<WindowSegment> box =
      windowSegments(view.projection * view.view, glm::vec2(size), scene_.fieldBoxEdges());
  background_.draw(targets_, scene_.flatGround(), raster, box, SceneRenderer::kFieldBoxColor);
  if (raster) {
    // Translucent items blend over the background and are hidden behind it.
    glBindTextureUnit(kSceneDepthUnit, targets_.sceneDepth());
    scene_.drawTranslucent();
  }
  particles.drawTrails(&view, targets_);
}

}  // namespace sandstorm
