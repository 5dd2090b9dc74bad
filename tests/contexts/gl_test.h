// GL tests run on an offscreen EGL context (llvmpipe on machines without a
// GPU). One context per test process, made current on the test thread.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "contexts/platform/egl_context.h"

namespace sandstorm {

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!context()) context() = std::make_unique<EglContext>();
    context()->makeCurrent();
  }
  static std::unique_ptr<EglContext>& context() {
    static std::unique_ptr<EglContext> c;
    return c;
  }
};

}  // namespace sandstorm
