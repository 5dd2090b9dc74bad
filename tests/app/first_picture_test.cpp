// The first picture a new user sees (scripts/run's out/downdraft.png): the
// helicopter's dust must be a cloud that stands out against the sand and the
// sky, not a texture on the ground. Measured as the issue asks: the same frame
// rendered with the dust and with it invisible (render.opacity_birth = 0,
// which changes nothing the simulation does); the dust must change at least a
// fifth of the picture's pixels by more than 8/255, and a fifth of the sky's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

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

Share measure(const std::string& name, const std::string& extra) {
  const auto with = test::scratchDir(name + "-dust"), without = test::scratchDir(name + "-clear");
  // scripts/run's frame count: the picture it writes.
  const std::string run = "--config tests/data/first-picture.toml --frames 300 " + extra;
  const auto a = runSandstorm(run + " --screenshot " + with.string());
  EXPECT_EQ(a.exitCode, 0) << a.output;
  const auto b =
      runSandstorm(run + " --set render.opacity_birth=0 --screenshot " + without.string());
  EXPECT_EQ(b.exitCode, 0) << b.output;
  if (a.exitCode != 0 || b.exitCode != 0) return {};
  const Image dust = readPng(with / "downdraft.png"), clear = readPng(without / "downdraft.png");
  EXPECT_EQ(dust.width, clear.width);
  if (dust.width != clear.width || dust.height != clear.height) return {};
  const Share s = dustShare(dust, clear);
  std::printf("%s: the dust changes %.1f%% of the picture and %.1f%% of the sky (%.1f%% of it)\n",
              name.c_str(), 100.0 * s.picture, 100.0 * s.sky, 100.0 * s.skyPixels);
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

TEST(FirstPicture, TheDustIsACloudAgainstSandAndSkyInTheLiveFlow) {
  const Share s = measure("first-picture-live", "");
  EXPECT_GT(s.skyPixels, 0.3) << "the camera sees the sky above the dunes";
  EXPECT_GE(s.picture, 0.2);
  EXPECT_GE(s.sky, 0.2);
}

TEST(FirstPicture, TheDustIsACloudAgainstSandAndSkyInTheAnalyticDownwash) {
  const Share s = measure("first-picture-analytic", "--set solver.enabled=false");
  EXPECT_GT(s.skyPixels, 0.3) << "the camera sees the sky above the dunes";
  EXPECT_GE(s.picture, 0.2);
  EXPECT_GE(s.sky, 0.2);
}

}  // namespace
}  // namespace sandstorm
