// Overlays on stereo walls: the legend and the menu are laid out for one
// eye's image and drawn into each at the same place (no disparity: on the
// wall's plane), so both eyes read them. Each test runs the app with and
// without the overlay and compares where each eye's image changed.
#include <gtest/gtest.h>

#include <cstdio>

#include <algorithm>
#include <iterator>

#include "core/util/image.h"
#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

using test::runSandstorm;

// Where an overlay changed each eye's image, relative to that image's corner
// (y down): the left eye's half (left or top) first.
struct EyeChanges {
  std::vector<glm::ivec2> first, second;
  glm::ivec2 eye{0};
};

EyeChanges eyeChanges(const Image& plain, const Image& with, bool sideBySide) {
  EyeChanges c;
  c.eye = sideBySide ? glm::ivec2(plain.width / 2, plain.height)
                     : glm::ivec2(plain.width, plain.height / 2);
  auto changes = [&](int x0, int y0) {
    std::vector<glm::ivec2> out;
    for (int y = 0; y < c.eye.y; ++y)
      for (int x = 0; x < c.eye.x; ++x)
        if (plain.at(x0 + x, y0 + y) != with.at(x0 + x, y0 + y)) out.push_back({x, y});
    return out;
  };
  c.first = changes(0, 0);
  c.second = sideBySide ? changes(c.eye.x, 0) : changes(0, c.eye.y);
  return c;
}

// Pixels changed in one eye's image and not at the same place in the other's.
std::size_t mismatched(const EyeChanges& c) {
  auto less = [](glm::ivec2 a, glm::ivec2 b) { return a.y != b.y ? a.y < b.y : a.x < b.x; };
  std::vector<glm::ivec2> out;
  std::set_symmetric_difference(c.first.begin(), c.first.end(), c.second.begin(), c.second.end(),
                                std::back_inserter(out), less);
  return out.size();
}

TEST(StereoOverlay, TheLegendIsInEachEyesImageAtTheSamePlace) {
  for (const char* wall : {"front", "left"}) {
    const auto without = test::scratchDir("legend-stereo-off"),
               with = test::scratchDir("legend-stereo-on");
    // The legend on the side-by-side wall (front), then on the top-bottom one (left).
    const std::string run = "--config tests/data/legend-stereo.toml --screenshot ",
                      only = std::string(wall) == "left" ? " --walls left" : "";
    const auto a = runSandstorm(run + without.string() + only);
    ASSERT_EQ(a.exitCode, 0) << a.output;
    const auto b = runSandstorm(run + with.string() + only + " --set render.legend=true");
    ASSERT_EQ(b.exitCode, 0) << b.output;
    const Image plain = readPng(without / (std::string(wall) + ".png")),
                legend = readPng(with / (std::string(wall) + ".png"));
    ASSERT_EQ(plain.width, legend.width);
    const EyeChanges c = eyeChanges(plain, legend, std::string(wall) == "front");
    EXPECT_GT(c.first.size(), 200u) << wall << ": no legend in the first eye's image";
    EXPECT_EQ(c.first, c.second) << wall << ": the eyes see the legend at different places";
    for (const glm::ivec2& p : c.first)
      if (p.x < c.eye.x / 5 || p.y < c.eye.y / 2) {
        ADD_FAILURE() << wall << ": a legend pixel at " << p.x << "," << p.y
                      << " outside the eye image's lower right";
        break;
      }
  }
}

// The menu on a stereo wall was laid out over the whole image: one eye saw
// the panel, the other the scene behind it (side by side), or the panel
// spanned both eyes' images (top-bottom). Now each eye sees all of it, and a
// click laid out for the eye's image reaches its widget: offscreen, and in a
// window (whose own size and mouse ImGui reads, cut to an eye's).
TEST(StereoOverlay, TheMenuIsInEachEyesImageAtTheSamePlaceAndTakesClicks) {
  struct Case {
    const char* config;
    bool sideBySide, window;
  };
  for (const Case c :
       {Case{"menu-stereo", true, false}, Case{"menu-stereo-top-bottom", false, false},
        Case{"window-stereo", true, true}}) {
    if (c.window && !test::haveXvfb()) {  // as the window tests do: say so, and test the rest
      std::printf("%s: skipped, xvfb-run is not installed (scripts/setup installs it)\n", c.config);
      continue;
    }
    auto run = [&](const std::string& args) {
      const std::string all = std::string("--config tests/data/") + c.config + ".toml " + args;
      return c.window ? test::runUnderXvfb(all) : runSandstorm(all);
    };
    const auto without = test::scratchDir("menu-stereo-off"),
               with = test::scratchDir("menu-stereo-on");
    // The menu shows while a script drives it (offscreen) or always (a window,
    // unless --no-menu); the script's click comes after these 4 frames.
    const auto a = run("--no-menu --screenshot " + without.string());
    ASSERT_EQ(a.exitCode, 0) << a.output;
    const auto b = run("--menu-script tests/data/menu-stereo.script --screenshot " + with.string());
    ASSERT_EQ(b.exitCode, 0) << b.output;
    const Image plain = readPng(without / "front.png"), menu = readPng(with / "front.png");
    ASSERT_EQ(plain.width, menu.width);
    const EyeChanges e = eyeChanges(plain, menu, c.sideBySide);
    // The panel (360 to 380 pixels wide, from (8, 8)) covers most of the eye's
    // image's left; it blends over each eye's own scene, so a faint pixel may
    // round to no change in one eye.
    const std::size_t panel = std::size_t(e.eye.x * e.eye.y) / 2;
    EXPECT_GT(e.first.size(), panel) << c.config << ": no panel in the left eye's image";
    EXPECT_GT(e.second.size(), panel) << c.config << ": no panel in the right eye's image";
    EXPECT_LT(mismatched(e), e.first.size() / 100) << c.config << ": the eyes see different panels";
    for (const glm::ivec2& p : e.first)
      if (p.x > 400 || p.y < 8) {
        ADD_FAILURE() << c.config << ": a panel pixel at " << p.x << "," << p.y
                      << " outside the eye image's upper left";
        break;
      }

    const auto session = test::scratchDir("menu-stereo-click") / "s.session";
    const auto click =
        run("--frames 12 --menu-script tests/data/menu-stereo.script --record " + session.string());
    ASSERT_EQ(click.exitCode, 0) << click.output;
    bool sized = false;
    for (const std::string& line : test::readLines(session))
      sized = sized || line.find("render.size") != std::string::npos;
    EXPECT_TRUE(sized) << c.config << ": the scripted click missed the size slider\n"
                       << click.output;
  }
}

}  // namespace
}  // namespace sandstorm
