#include "contexts/render/view_targets.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <vector>

#include "contexts/gl/out_of_memory.h"
#include "core/util/error.h"
#include "core/util/image.h"

namespace sandstorm {
namespace {

gl::Texture texture2D(GLenum format, glm::ivec2 size) {
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, format, size.x, size.y);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

void checkComplete(GLuint fbo, const char* what) {
  const GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error(concat("ViewTargets: the ", what, " framebuffer is incomplete (status 0x", std::hex,
                       status, ")"));
}

// An image the GPU can hold: within its largest texture and renderbuffer side.
void checkImageSize(glm::ivec2 size) {
  GLint texture = 0, renderbuffer = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  const int limit = std::min(texture, renderbuffer);
  if (size.x > limit || size.y > limit)
    throw Error(concat("an image of ", size.x, "x", size.y,
                       " pixels is larger than this GPU draws (", limit,
                       " pixels a side); choose a smaller wall or --movie-size"));
}

// After allocating a size's images: the GPU's memory held them.
void checkAllocated(const gl::OutOfMemoryCheck& memory, glm::ivec2 size, const char* what) {
  if (memory.failed())
    throw Error(concat("the GPU is out of memory for the ", what, " images of ", size.x, "x",
                       size.y, " pixels; choose a smaller wall or --movie-size"));
}

}  // namespace

void ViewTargets::resize(glm::ivec2 size) {
  if (size == size_) return;
  if (size.x <= 0 || size.y <= 0)
    throw Error(concat("ViewTargets: bad size ", size.x, "x", size.y));
  checkImageSize(size);
  size_ = size;
  const gl::OutOfMemoryCheck memory;
  sceneColor_ = texture2D(GL_RGBA8, size);
  sceneDepth_ = texture2D(GL_R32F, size);
  itemsDepth_ = texture2D(GL_DEPTH_COMPONENT32F, size);
  particleColor_ = texture2D(GL_RGBA16F, size);
  particleNormal_ = texture2D(GL_RGBA16F, size);
  particleLight_ = texture2D(GL_R16F, size);
  checkAllocated(memory, size, "view's");

  sceneFbo_ = gl::createFramebuffer();
  glNamedFramebufferTexture(sceneFbo_.id(), GL_COLOR_ATTACHMENT0, sceneColor_.id(), 0);
  glNamedFramebufferTexture(sceneFbo_.id(), GL_DEPTH_ATTACHMENT, itemsDepth_.id(), 0);
  checkComplete(sceneFbo_.id(), "scene");

  particleFbo_ = gl::createFramebuffer();
  glNamedFramebufferTexture(particleFbo_.id(), GL_COLOR_ATTACHMENT0, particleColor_.id(), 0);
  glNamedFramebufferTexture(particleFbo_.id(), GL_COLOR_ATTACHMENT1, particleNormal_.id(), 0);
  glNamedFramebufferTexture(particleFbo_.id(), GL_COLOR_ATTACHMENT2, particleLight_.id(), 0);
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glNamedFramebufferDrawBuffers(particleFbo_.id(), 3, buffers);
  checkComplete(particleFbo_.id(), "particle");
}

void OutputTarget::resize(glm::ivec2 size) {
  if (size == size_) return;
  if (size.x <= 0 || size.y <= 0)
    throw Error(concat("OutputTarget: bad size ", size.x, "x", size.y));
  checkImageSize(size);
  size_ = size;
  const gl::OutOfMemoryCheck memory;
  color_ = texture2D(GL_RGBA8, size);
  depth_ = gl::createRenderbuffer();
  glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT24, size.x, size.y);
  checkAllocated(memory, size, "wall's");
  fbo_ = gl::createFramebuffer();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
  glNamedFramebufferRenderbuffer(fbo_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  checkComplete(fbo_.id(), "output");
}

Image OutputTarget::readPixels() const {
  return readFramebuffer(fbo_.id(), GL_COLOR_ATTACHMENT0, size_);
}

namespace {

// The buffers bound to indexed uniform and storage binding points, unbound
// for a read into the process's memory and bound again after it. At such a
// read NVIDIA's driver moved every buffer so bound (the particles' too) from
// video to host memory (GL message 131186): 0.7 GB a wall of 10^7 particles,
// and seconds, at each screenshot and movie frame (docs/PERFORMANCE.md).
class BoundBuffersSetAside {
 public:
  BoundBuffersSetAside() {
    for (const Target& t : kTargets) {
      // The general binding first: binding an index sets it too.
      GLint general = 0;
      glGetIntegerv(t.generalBinding, &general);
      general_.push_back({t.target, 0, GLuint(general), 0, 0});
      GLint count = 0;
      glGetIntegerv(t.maxBindings, &count);
      for (GLuint i = 0; i < GLuint(count); ++i) {
        GLint id = 0;
        glGetIntegeri_v(t.binding, i, &id);
        if (id == 0) continue;
        Binding b{t.target, i, GLuint(id), 0, 0};
        glGetInteger64i_v(t.start, i, &b.start);
        glGetInteger64i_v(t.size, i, &b.size);
        bindings_.push_back(b);
        glBindBufferBase(t.target, i, 0);
      }
      glBindBuffer(t.target, 0);
    }
  }
  ~BoundBuffersSetAside() {
    for (const Binding& b : bindings_) {
      if (b.size > 0)
        glBindBufferRange(b.target, b.index, b.id, GLintptr(b.start), GLsizeiptr(b.size));
      else
        glBindBufferBase(b.target, b.index, b.id);
    }
    for (const Binding& b : general_)
      glBindBuffer(b.target, b.id);
  }
  BoundBuffersSetAside(const BoundBuffersSetAside&) = delete;
  BoundBuffersSetAside& operator=(const BoundBuffersSetAside&) = delete;

 private:
  struct Target {
    GLenum target, maxBindings, binding, start, size, generalBinding;
  };
  static constexpr Target kTargets[] = {
      {GL_SHADER_STORAGE_BUFFER, GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS,
       GL_SHADER_STORAGE_BUFFER_BINDING, GL_SHADER_STORAGE_BUFFER_START,
       GL_SHADER_STORAGE_BUFFER_SIZE, GL_SHADER_STORAGE_BUFFER_BINDING},
      {GL_UNIFORM_BUFFER, GL_MAX_UNIFORM_BUFFER_BINDINGS, GL_UNIFORM_BUFFER_BINDING,
       GL_UNIFORM_BUFFER_START, GL_UNIFORM_BUFFER_SIZE, GL_UNIFORM_BUFFER_BINDING}};
  struct Binding {
    GLenum target;
    GLuint index, id;
    GLint64 start, size;
  };
  std::vector<Binding> bindings_, general_;
};

}  // namespace

Image readFramebuffer(std::uint32_t framebuffer, std::uint32_t buffer, glm::ivec2 size) {
  const BoundBuffersSetAside setAside;
  Image image{size.x, size.y,
              std::vector<std::uint8_t>(std::size_t(size.x) * std::size_t(size.y) * 4)};
  std::vector<std::uint8_t> flipped(image.rgba.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glReadBuffer(buffer);
  glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  const std::size_t row = std::size_t(size.x) * 4;
  for (int y = 0; y < size.y; ++y)  // GL's first row is the bottom one
    std::copy_n(flipped.data() + std::size_t(size.y - 1 - y) * row, row,
                image.rgba.data() + std::size_t(y) * row);
  return image;
}

}  // namespace sandstorm
