// Reading an image back (OutputTarget::readPixels, readFramebuffer): the
// pixels the target holds, top row first, and the context's buffer bindings
// as they were before (the read sets them aside: NVIDIA's driver moved bound
// buffers to host memory at such a read), ranges included.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "contexts/gl/objects.h"
#include "contexts/render/view_targets.h"
#include "core/util/image.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class ReadBackTest : public GlTest {};

TEST_F(ReadBackTest, PixelsComeBackTopRowFirstAndTheBufferBindingsStay) {
  OutputTarget target;
  target.resize({4, 3});
  // Red below, green in the top row: a scissored clear each.
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 2, 4, 1);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  gl::Buffer storage = gl::createBuffer(), uniforms = gl::createBuffer();
  glNamedBufferStorage(storage.id(), 4096, nullptr, 0);
  glNamedBufferStorage(uniforms.id(), 4096, nullptr, 0);
  GLint align = 1;
  glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &align);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, storage.id());
  glBindBufferRange(GL_UNIFORM_BUFFER, 2, uniforms.id(), align, 256);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, uniforms.id());  // the general binding too

  const Image image = target.readPixels();
  ASSERT_EQ(image.width, 4);
  ASSERT_EQ(image.height, 3);
  EXPECT_EQ(image.at(1, 0), glm::u8vec4(0, 255, 0, 255));  // the top row
  EXPECT_EQ(image.at(1, 2), glm::u8vec4(255, 0, 0, 255));

  GLint id = 0;
  GLint64 start = -1, size = -1;
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 3, &id);
  EXPECT_EQ(GLuint(id), storage.id());
  glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 2, &id);
  EXPECT_EQ(GLuint(id), uniforms.id());
  glGetInteger64i_v(GL_UNIFORM_BUFFER_START, 2, &start);
  glGetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, 2, &size);
  EXPECT_EQ(start, align);
  EXPECT_EQ(size, 256);
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &id);
  EXPECT_EQ(GLuint(id), uniforms.id());
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 4, &id);
  EXPECT_EQ(id, 0);  // nothing bound where nothing was
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, 0);
  glBindBufferBase(GL_UNIFORM_BUFFER, 2, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

}  // namespace
}  // namespace sandstorm
