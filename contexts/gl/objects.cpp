#include "contexts/gl/objects.h"

#include <epoxy/gl.h>

namespace sandstorm::gl {

void destroyObject(ObjectKind kind, std::uintptr_t handle) noexcept {
  const GLuint id = GLuint(handle);
  switch (kind) {
    case ObjectKind::Buffer:
      glDeleteBuffers(1, &id);
      break;
    case ObjectKind::VertexArray:
      glDeleteVertexArrays(1, &id);
      break;
    case ObjectKind::Texture:
      glDeleteTextures(1, &id);
      break;
    case ObjectKind::Framebuffer:
      glDeleteFramebuffers(1, &id);
      break;
    case ObjectKind::Renderbuffer:
      glDeleteRenderbuffers(1, &id);
      break;
    case ObjectKind::TransformFeedback:
      glDeleteTransformFeedbacks(1, &id);
      break;
    case ObjectKind::Query:
      glDeleteQueries(1, &id);
      break;
    case ObjectKind::Program:
      glDeleteProgram(id);
      break;
    case ObjectKind::Shader:
      glDeleteShader(id);
      break;
    case ObjectKind::Sync:
      glDeleteSync(reinterpret_cast<GLsync>(handle));
      break;
  }
}

Buffer createBuffer() {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  return Buffer::wrap(id);
}

VertexArray createVertexArray() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray::wrap(id);
}

Texture createTexture(std::uint32_t target) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  return Texture::wrap(id);
}

Framebuffer createFramebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return Framebuffer::wrap(id);
}

Renderbuffer createRenderbuffer() {
  GLuint id = 0;
  glCreateRenderbuffers(1, &id);
  return Renderbuffer::wrap(id);
}

TransformFeedback createTransformFeedback() {
  GLuint id = 0;
  glCreateTransformFeedbacks(1, &id);
  return TransformFeedback::wrap(id);
}

Query createQuery(std::uint32_t target) {
  GLuint id = 0;
  glCreateQueries(target, 1, &id);
  return Query::wrap(id);
}

Sync createFence() {
  return Sync::wrap(
      reinterpret_cast<std::uintptr_t>(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0)));
}

}  // namespace sandstorm::gl
