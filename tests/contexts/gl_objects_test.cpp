// GL object ownership and shader errors.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <type_traits>

#include "contexts/gl/objects.h"
#include "contexts/gl/out_of_memory.h"
#include "contexts/gl/program.h"
#include "core/util/error.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

static_assert(!std::is_copy_constructible_v<gl::Buffer>);
static_assert(!std::is_copy_assignable_v<gl::Texture>);
static_assert(std::is_nothrow_move_constructible_v<gl::Framebuffer>);
static_assert(std::is_nothrow_move_assignable_v<gl::TransformFeedback>);

class GlObjectsTest : public GlTest {};

TEST_F(GlObjectsTest, OneOwnerDeletesEachObjectOnce) {
  gl::Buffer a = gl::createBuffer();
  const std::uint32_t id = a.id();
  ASSERT_NE(id, 0u);
  EXPECT_TRUE(glIsBuffer(id));
  gl::Buffer b = std::move(a);
  EXPECT_EQ(a.id(), 0u);  // the source is empty after a move
  EXPECT_EQ(b.id(), id);
  { gl::Buffer c = std::move(b); }  // c deletes it
  EXPECT_FALSE(glIsBuffer(id));
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
  const std::uint32_t tid = t.id();
  t = gl::createTexture(GL_TEXTURE_2D);  // assignment deletes the old one
  EXPECT_FALSE(glIsTexture(tid));
  EXPECT_NE(t.id(), tid);
}

// The driver's report of an allocation that ran out of memory is an error on
// the terminal, unless the allocation is checked: then the check's own
// message (naming the setting to lower) is the one the user reads.
TEST_F(GlObjectsTest, ACheckedAllocationsOutOfMemoryReportIsNotPrintedAsAnError) {
  // The callback runs before glDebugMessageInsert returns (a driver may
  // otherwise call it later, from its own thread).
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  const auto printed = [](const char* message) {
    testing::internal::CaptureStderr();
    glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_ERROR, 1,
                         GL_DEBUG_SEVERITY_HIGH, -1, message);
    return testing::internal::GetCapturedStderr();
  };
  const char* outOfMemory = "GL_OUT_OF_MEMORY in glNamedBufferStorage";
  EXPECT_NE(printed(outOfMemory).find("[sandstorm error] GL (1): GL_OUT_OF_MEMORY"),
            std::string::npos);
  {
    const gl::OutOfMemoryCheck check;
    EXPECT_EQ(printed(outOfMemory), "");
    EXPECT_EQ(printed("Out of memory allocating a buffer"), "");
    // Other errors still show while the check lives.
    EXPECT_NE(printed("GL_INVALID_VALUE in glNamedBufferStorage").find("[sandstorm error]"),
              std::string::npos);
    EXPECT_FALSE(check.failed());
  }
  EXPECT_NE(printed(outOfMemory).find("[sandstorm error]"), std::string::npos);
  glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
}

TEST_F(GlObjectsTest, CompileErrorsNameTheFileAndPrintTheLog) {
  try {
    // A define that breaks the shader's own code: `vec4` no longer names a type.
    gl::Program broken(std::vector<std::string>{"fullscreen.vert", "anaglyph.frag"}, {"vec4 int"});
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("shaders/fullscreen.vert"), std::string::npos) << m;
    EXPECT_NE(m.find("error"), std::string::npos) << m;  // the driver's log
  }
  try {
    gl::Program missing(std::vector<std::string>{"nowhere.vert"});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'nowhere.vert'"), std::string::npos) << e.what();
  }
}

TEST_F(GlObjectsTest, IncludesKeepLineNumbersAndSayWhichFileIsWhich) {
  std::vector<std::string> files;
  const std::string source = gl::preprocessShader("particle_update.geom", {"X 1"}, files);
  ASSERT_GE(files.size(), 3u);
  EXPECT_EQ(files[0], "particle_update.geom");
  EXPECT_NE(std::find(files.begin(), files.end(), "sim_block.glsl"), files.end());
  EXPECT_EQ(source.find("#version"), 0u);
  EXPECT_NE(source.find("#define X 1"), std::string::npos);
  EXPECT_NE(source.find("#line 1 1"),
            std::string::npos);  // the first include starts at its own line 1
}

}  // namespace
}  // namespace sandstorm
