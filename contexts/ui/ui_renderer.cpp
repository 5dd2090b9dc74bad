#include "contexts/ui/ui_renderer.h"

#include <epoxy/gl.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace sandstorm {

UiRenderer::UiRenderer(const UiFont& font)
    : program_(std::vector<std::string>{"ui.vert", "ui.frag"}),
      font_(gl::createTexture(GL_TEXTURE_2D)),
      vao_(gl::createVertexArray()) {
  glTextureStorage2D(font_.id(), 1, GL_RGBA8, font.width, font.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(font_.id(), 0, 0, 0, font.width, font.height, GL_RGBA, GL_UNSIGNED_BYTE,
                      font.rgba.data());
  glTextureParameteri(font_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(font_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnableVertexArrayAttrib(vao_.id(), 0);
  glEnableVertexArrayAttrib(vao_.id(), 1);
  glEnableVertexArrayAttrib(vao_.id(), 2);
  glVertexArrayAttribFormat(vao_.id(), 0, 2, GL_FLOAT, GL_FALSE, offsetof(UiVertex, position));
  glVertexArrayAttribFormat(vao_.id(), 1, 2, GL_FLOAT, GL_FALSE, offsetof(UiVertex, uv));
  glVertexArrayAttribFormat(vao_.id(), 2, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(UiVertex, color));
  for (GLuint a = 0; a < 3; ++a)
    glVertexArrayAttribBinding(vao_.id(), a, 0);
}

void UiRenderer::drawWindow(const UiDrawData& data, glm::ivec2 size) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const float backdrop[4] = {0.12f, 0.12f, 0.14f, 1.0f};
  glClearNamedFramebufferfv(0, GL_COLOR, 0, backdrop);
  draw(data, size);
}

void UiRenderer::draw(const UiDrawData& d, glm::ivec4 viewport) {
  const glm::ivec2 at(viewport.x, viewport.y), fb(viewport.z, viewport.w);
  if (d.commands.empty() || fb.x <= 0 || fb.y <= 0) return;
  if (d.vertices.size() > vertexCapacity_) {
    vertexCapacity_ = d.vertices.size() * 2;
    vertices_ = gl::createBuffer();
    glNamedBufferStorage(vertices_.id(), GLsizeiptr(vertexCapacity_ * sizeof(UiVertex)), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(UiVertex));
  }
  if (d.indices.size() > indexCapacity_) {
    indexCapacity_ = d.indices.size() * 2;
    indices_ = gl::createBuffer();
    glNamedBufferStorage(indices_.id(), GLsizeiptr(indexCapacity_ * 2), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
  }
  glNamedBufferSubData(vertices_.id(), 0, GLsizeiptr(d.vertices.size() * sizeof(UiVertex)),
                       d.vertices.data());
  glNamedBufferSubData(indices_.id(), 0, GLsizeiptr(d.indices.size() * 2), d.indices.data());

  glViewport(at.x, at.y, fb.x, fb.y);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_SCISSOR_TEST);
  const glm::mat4 projection = glm::ortho(d.displayPos.x, d.displayPos.x + d.displaySize.x,
                                          d.displayPos.y + d.displaySize.y, d.displayPos.y);
  program_.use();
  glProgramUniformMatrix4fv(program_.id(), 0, 1, GL_FALSE, glm::value_ptr(projection));
  glBindTextureUnit(0, font_.id());
  glBindVertexArray(vao_.id());
  for (const UiCommand& c : d.commands) {
    const glm::vec4 clip = (c.clip - glm::vec4(d.displayPos, d.displayPos)) *
                           glm::vec4(d.framebufferScale, d.framebufferScale);
    if (clip.z <= clip.x || clip.w <= clip.y) continue;
    glScissor(at.x + int(clip.x), at.y + int(float(fb.y) - clip.w), int(clip.z - clip.x),
              int(clip.w - clip.y));
    glDrawElementsBaseVertex(GL_TRIANGLES, GLsizei(c.indexCount), GL_UNSIGNED_SHORT,
                             reinterpret_cast<const void*>(std::uintptr_t(c.firstIndex) * 2),
                             c.vertexOffset);
  }
  glBindVertexArray(0);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
}

}  // namespace sandstorm
