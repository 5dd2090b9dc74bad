#include "contexts/scene/wand_renderer.h"

#include <epoxy/gl.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace sandstorm {
namespace {

// A box from a to b, `width` across (room metres), as a model matrix for the unit cube in the room.
glm::mat4 beam(const glm::vec3& a, const glm::vec3& b, float width) {
  const glm::vec3 d = b - a;
  const glm::vec3 along = glm::length(d) > 1e-6f ? glm::normalize(d) : glm::vec3(0, 1, 0);
  const glm::vec3 helper = std::abs(along.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(along, helper));
  const glm::vec3 v = glm::cross(along, u);
  return glm::mat4(glm::vec4(u * width, 0.0f), glm::vec4(v * width, 0.0f), glm::vec4(d, 0.0f),
                   glm::vec4(0.5f * (a + b), 1.0f));
}

glm::mat4 cubeAt(const glm::vec3& centre, float size) {
  return glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(size));
}

}  // namespace

WandRenderer::WandRenderer() : mesh_(std::vector<std::string>{"mesh.vert", "mesh.frag"}) {}

void WandRenderer::set(const WandRay& ray, const Navigation& navigation,
                       std::vector<glm::vec3> handles) {
  ray_ = ray;
  navigation_ = navigation;
  handles_ = std::move(handles);
}

void WandRenderer::box(const glm::mat4& roomModel, const glm::vec3& color) const {
  // The scene's view looks at the world: room -> world first.
  const glm::mat4 model = glm::inverse(navigation_.worldToRoom()) * roomModel;
  glProgramUniformMatrix4fv(mesh_.id(), 0, 1, GL_FALSE, glm::value_ptr(model));
  glProgramUniform4f(mesh_.id(), 1, color.x, color.y, color.z, 1.0f);
  cube_.draw();
}

void WandRenderer::draw() const {
  if (!visible()) return;
  mesh_.use();
  box(beam(ray_.origin, ray_.end, kBeamWidth), {1.0f, 0.85f, 0.2f});
  const glm::mat4 worldToRoom = navigation_.worldToRoom();
  for (std::size_t i = 0; i < handles_.size(); ++i) {
    const glm::vec3 room = glm::vec3(worldToRoom * glm::vec4(handles_[i], 1.0f));
    const bool chosen = int(i) == ray_.emitter;
    box(cubeAt(room, kHandleSize), ray_.holding && chosen ? glm::vec3(1.0f, 0.45f, 0.1f)
                                                          : (chosen ? glm::vec3(1.0f, 0.7f, 0.3f)
                                                                    : glm::vec3(0.3f, 0.5f, 0.8f)));
  }
  if (ray_.target != WandTarget::None && !ray_.holding) {
    const glm::vec3 color = ray_.target == WandTarget::Menu      ? glm::vec3(1.0f)
                            : ray_.target == WandTarget::Emitter ? glm::vec3(1.0f, 0.45f, 0.1f)
                                                                 : glm::vec3(0.3f, 1.0f, 0.4f);
    box(cubeAt(ray_.end, kMarkerSize), color);
  }
  glBindVertexArray(0);
}

}  // namespace sandstorm
