// drawProgressBar: the bar a wall shows in each eye's view while it waits for
// its first frame (and the loading window's): the viewport cleared dark, a
// grey frame round the bar, the share done filled from the left, nothing
// drawn outside the viewport.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "contexts/render/view_targets.h"
#include "contexts/ui/progress_bar.h"
#include "core/cave/wall_views.h"
#include "core/util/image.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class ProgressBarTest : public GlTest {};

// Colours as drawProgressBar clears them, in 8 bits (within 1: how a driver
// rounds 229.5 is its own).
const glm::u8vec4 kBackground(20, 23, 28, 255), kFrame(140, 148, 158, 255), kEmpty(36, 38, 46, 255),
    kDone(230, 158, 56, 255);

::testing::AssertionResult near(glm::u8vec4 got, glm::u8vec4 want) {
  const glm::ivec4 d = glm::abs(glm::ivec4(got) - glm::ivec4(want));
  if (std::max({d.x, d.y, d.z}) <= 1) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "got " << int(got.x) << "," << int(got.y) << "," << int(got.z) << ", want "
         << int(want.x) << "," << int(want.y) << "," << int(want.z);
}

TEST_F(ProgressBarTest, EachEyeShowsTheShareDoneInItsMiddle) {
  // The eyes of a 400x120 wall in a target 20 rows taller: the rows above stay blue.
  const glm::ivec2 size(400, 140);
  OutputTarget target;
  target.resize(size);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
  glViewport(0, 0, size.x, size.y);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const std::vector<glm::ivec4> eyes = eyeViewports(StereoMode::SideBySide, {400, 120});
  ASSERT_EQ(eyes.size(), 2u);
  for (const glm::ivec4& eye : eyes) {
    const glm::ivec4 bar = centredBar(eye, 0.6f);
    EXPECT_EQ(bar, glm::ivec4(eye.x + 40, 57, 120, 6));  // 60% of 200, 6 pixels: 120/40 is less
    drawProgressBar(eye, bar, 0.25);
  }
  GLboolean scissor = GL_TRUE;
  glGetBooleanv(GL_SCISSOR_TEST, &scissor);
  EXPECT_EQ(scissor, GL_FALSE);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  const Image image = target.readPixels();  // top row first
  const auto at = [&](int x, int y) { return image.at(x, size.y - 1 - y); };
  for (int e = 0; e < 2; ++e) {
    const int x0 = 200 * e;
    SCOPED_TRACE(e);
    EXPECT_TRUE(near(at(x0 + 5, 5), kBackground));
    EXPECT_TRUE(near(at(x0 + 195, 115), kBackground));
    EXPECT_TRUE(near(at(x0 + 39, 59), kFrame));   // left of the bar
    EXPECT_TRUE(near(at(x0 + 100, 56), kFrame));  // below it
    EXPECT_TRUE(near(at(x0 + 41, 59), kDone));    // a quarter of 120 pixels: 30
    EXPECT_TRUE(near(at(x0 + 69, 59), kDone));
    EXPECT_TRUE(near(at(x0 + 70, 59), kEmpty));
    EXPECT_TRUE(near(at(x0 + 159, 62), kEmpty));
    EXPECT_TRUE(near(at(x0 + 160, 59), kFrame));  // right of it
  }
  for (int x : {0, 150, 399})
    EXPECT_TRUE(near(at(x, 130), glm::u8vec4(0, 0, 255, 255))) << x;
}

}  // namespace
}  // namespace sandstorm
