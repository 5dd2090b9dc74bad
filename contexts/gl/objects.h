// One move-only owner per OpenGL object: the id is deleted exactly once, on the
// context that is current when the owner dies (which must be the context that
// made it, or one sharing with it). Copying is impossible; moving leaves the
// source empty (id 0). release() gives the id up; wrap() adopts one.
//
//   gl::Buffer vbo = gl::createBuffer();
//   glNamedBufferStorage(vbo.id(), size, data, 0);
#pragma once

#include <cstdint>
#include <utility>

namespace sandstorm::gl {

enum class ObjectKind {
  Buffer,
  VertexArray,
  Texture,
  Framebuffer,
  Renderbuffer,
  TransformFeedback,
  Query,
  Program,
  Shader,
  Sync,
};

// Deletes one object of the kind (defined next to the GL calls, in objects.cpp).
void destroyObject(ObjectKind kind, std::uintptr_t id) noexcept;

template <ObjectKind Kind>
class Object {
 public:
  Object() = default;
  static Object wrap(std::uintptr_t id) { return Object(id); }
  ~Object() { reset(); }

  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  Object(Object&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  Object& operator=(Object&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }

  // GL names are 32-bit; sync objects are pointers, hence uintptr_t storage.
  std::uint32_t id() const { return std::uint32_t(id_); }
  std::uintptr_t handle() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  std::uintptr_t release() { return std::exchange(id_, 0); }
  void reset() {
    if (id_) destroyObject(Kind, std::exchange(id_, 0));
  }

 private:
  explicit Object(std::uintptr_t id) : id_(id) {}
  std::uintptr_t id_ = 0;
};

using Buffer = Object<ObjectKind::Buffer>;
using VertexArray = Object<ObjectKind::VertexArray>;
using Texture = Object<ObjectKind::Texture>;
using Framebuffer = Object<ObjectKind::Framebuffer>;
using Renderbuffer = Object<ObjectKind::Renderbuffer>;
using TransformFeedback = Object<ObjectKind::TransformFeedback>;
using Query = Object<ObjectKind::Query>;
using ProgramObject = Object<ObjectKind::Program>;
using ShaderObject = Object<ObjectKind::Shader>;
using Sync = Object<ObjectKind::Sync>;

// Creation through the 4.5 direct-state-access entry points. `target` is a GL
// enum (GL_TEXTURE_3D, GL_TIME_ELAPSED, ...).
Buffer createBuffer();
VertexArray createVertexArray();
Texture createTexture(std::uint32_t target);
Framebuffer createFramebuffer();
Renderbuffer createRenderbuffer();
TransformFeedback createTransformFeedback();
Query createQuery(std::uint32_t target);
Sync createFence();

}  // namespace sandstorm::gl
