// The first picture a new user sees (scripts/run's out/downdraft.png): the
// helicopter's dust must be a cloud that stands out against the sand and the
// sky, not a texture on the ground. Measured as the issue asks: the same frame
// rendered with the dust and with it invisible (render.opacity_birth = 0,
// which changes nothing the simulation does); the dust must change at least a
// fifth of the picture's pixels by more than 8/255, and a fifth of the sky's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "core/config/app_config.h"
#include "core/util/image.h"
#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

using test::runSandstorm;

struct Share {
  double picture = 0.0;  // of all pixels, those the dust changes
  double sky = 0.0;      // of the sky's pixels, those the dust changes
  double skyPixels = 0.0;
};

// The sky: in each column of the dustless picture, the pixels above the
// first sand-coloured one (red above blue by more than 35/255: the sand is
// 38 and more, the sky's haze down to the horizon at most 32 in the demo).
Share dustShare(const Image& dust, const Image& clear) {
  Share s;
  double changed = 0.0, sky = 0.0, skyChanged = 0.0;
  for (int x = 0; x < clear.width; ++x) {
    bool inSky = true;
    for (int y = 0; y < clear.height; ++y) {
      const glm::ivec4 a(dust.at(x, y)), b(clear.at(x, y));
      const glm::ivec4 d = glm::abs(a - b);
      const bool differs = std::max({d.x, d.y, d.z}) > 8;
      inSky = inSky && b.x - b.z <= 35;
      changed += differs ? 1.0 : 0.0;
      if (inSky) {
        sky += 1.0;
        skyChanged += differs ? 1.0 : 0.0;
      }
    }
  }
  const double pixels = double(clear.width) * double(clear.height);
  s.picture = changed / pixels;
  s.sky = skyChanged / std::max(sky, 1.0);
  s.skyPixels = sky / pixels;
  return s;
}

// Frame `frames - 1`, scripts/run's 300 frames: the picture it writes. Returns
// the wall's image, or an empty one (the failure reported) when the run failed.
Image render(const std::string& name, const std::string& extra, int frames = 300) {
  const auto dir = test::scratchDir(name);
  const auto r =
      runSandstorm("--config tests/data/first-picture.toml --frames " + std::to_string(frames) +
                   " " + extra + " --screenshot " + dir.string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return r.exitCode == 0 ? readPng(dir / "downdraft.png") : Image{};
}

Share measure(const char* name, const Image& dust, const Image& clear) {
  EXPECT_EQ(dust.width, clear.width);
  EXPECT_EQ(dust.height, clear.height);
  if (dust.width == 0 || dust.width != clear.width || dust.height != clear.height) return {};
  const Share s = dustShare(dust, clear);
  std::printf("%s: the dust changes %.1f%% of the picture and %.1f%% of the sky (%.1f%% of it)\n",
              name, 100.0 * s.picture, 100.0 * s.sky, 100.0 * s.skyPixels);
  return s;
}

TEST(FirstPicture, TheTestSeesTheDemoFromTheDemosCamera) {
  const AppConfig demo = loadConfig(SANDSTORM_SOURCE_DIR "/config/downdraft.toml");
  const AppConfig small = loadConfig(SANDSTORM_SOURCE_DIR "/tests/data/first-picture.toml");
  ASSERT_EQ(demo.walls.size(), 1u);
  ASSERT_EQ(small.walls.size(), 1u);
  ASSERT_TRUE(demo.walls[0].camera && small.walls[0].camera);
  EXPECT_EQ(demo.walls[0].camera->position, small.walls[0].camera->position);
  EXPECT_EQ(demo.walls[0].camera->target, small.walls[0].camera->target);
  EXPECT_EQ(demo.walls[0].camera->fovDegrees, small.walls[0].camera->fovDegrees);
  const glm::ivec2 size = demo.walls[0].window->size;
  EXPECT_EQ(size.x * 9, size.y * 16) << "the test's 320 x 180 keeps the demo's aspect";
}

// The live flow (the demo's) and the analytic wash (solver.enabled = false)
// against one dustless picture: invisible dust casts no shadow either, so
// neither the flow nor the frame changes it (its first frame and its 300th
// were compared once, byte for byte the same PNG): it is rendered after one
// frame, not 300.
TEST(FirstPicture, TheDustIsACloudAgainstSandAndSkyInBothFlows) {
  const Image clear = render("first-picture-clear", "--set render.opacity_birth=0", 1);
  for (const auto& [name, extra] :
       {std::pair<const char*, const char*>{"live flow", ""},
        std::pair<const char*, const char*>{"analytic wash", "--set solver.enabled=false"}}) {
    SCOPED_TRACE(name);
    const Share s = measure(name, render("first-picture-dust", extra), clear);
    EXPECT_GT(s.skyPixels, 0.3) << "the camera sees the sky above the dunes";
    EXPECT_GE(s.picture, 0.2);
    EXPECT_GE(s.sky, 0.2);
  }
}

}  // namespace
}  // namespace sandstorm
