// The movie's layout (the walls unfolded as a CAVE's cross), its compositing
// and its option parsing, against placements worked out by hand.
#include <gtest/gtest.h>

#include "core/movie/movie_compositor.h"
#include "core/movie/movie_layout.h"
#include "core/movie/movie_spec.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// A 3 m CAVE around the origin, floor at z = 0, as config/cave4.toml has it.
WallCorners wall(glm::vec3 ll, glm::vec3 lr, glm::vec3 ul) {
  return {ll, lr, ul};
}
const WallCorners kFront = wall({-1.5, 1.5, 0}, {1.5, 1.5, 0}, {-1.5, 1.5, 3});
const WallCorners kLeft = wall({-1.5, -1.5, 0}, {-1.5, 1.5, 0}, {-1.5, -1.5, 3});
const WallCorners kRight = wall({1.5, 1.5, 0}, {1.5, -1.5, 0}, {1.5, 1.5, 3});
const WallCorners kFloor = wall({-1.5, -1.5, 0}, {1.5, -1.5, 0}, {-1.5, 1.5, 0});
const WallCorners kCeiling = wall({-1.5, 1.5, 3}, {1.5, 1.5, 3}, {-1.5, -1.5, 3});
const WallCorners kBack = wall({1.5, -1.5, 0}, {-1.5, -1.5, 0}, {1.5, -1.5, 3});

MovieWallShape shape(const WallCorners& c, glm::ivec2 image = {64, 64}) {
  return {c, image, 1.0f};
}

void expectPlaced(const MoviePlacement& p, glm::dvec2 origin, glm::dvec2 right, glm::dvec2 up) {
  constexpr double kTol = 1e-6;  // corners are floats
  EXPECT_NEAR(p.origin.x, origin.x, kTol);
  EXPECT_NEAR(p.origin.y, origin.y, kTol);
  EXPECT_NEAR(p.right.x, right.x, kTol);
  EXPECT_NEAR(p.right.y, right.y, kTol);
  EXPECT_NEAR(p.up.x, up.x, kTol);
  EXPECT_NEAR(p.up.y, up.y, kTol);
}

TEST(MovieLayout, TheCaveUnfoldsAsItsCrossWithEveryWallUpright) {
  const auto p =
      unfoldWalls({shape(kFront), shape(kLeft), shape(kRight), shape(kFloor), shape(kCeiling)});
  ASSERT_EQ(p.size(), 5u);
  expectPlaced(p[0], {0, 0}, {3, 0}, {0, 3});   // the front, where it starts
  expectPlaced(p[1], {-3, 0}, {3, 0}, {0, 3});  // the left wall turned out to its left
  expectPlaced(p[2], {3, 0}, {3, 0}, {0, 3});   // the right wall to its right
  expectPlaced(p[3], {0, -3}, {3, 0}, {0, 3});  // the floor below, its far edge at the front's foot
  expectPlaced(p[4], {0, 3}, {3, 0},
               {0, 3});  // the ceiling above, its front edge at the front's top
}

TEST(MovieLayout, TheBackWallUnfoldsBeyondASideWithoutCoveringAnything) {
  const auto p = unfoldWalls({shape(kFront), shape(kLeft), shape(kRight), shape(kBack)});
  // Through the left wall, whose placement comes first: left of it, upright.
  expectPlaced(p[3], {-6, 0}, {3, 0}, {0, 3});
}

TEST(MovieLayout, TheCrossUnfoldsFromTheFrontWhateverTheWallsOrder) {
  // As config/cave4-desktop.toml lists them: the left wall first. The floor
  // meets the left wall too, but joins the front, placed before it.
  const auto p = unfoldWalls({shape(kLeft), shape(kFront), shape(kRight), shape(kFloor)}, 1);
  expectPlaced(p[1], {0, 0}, {3, 0}, {0, 3});
  expectPlaced(p[0], {-3, 0}, {3, 0}, {0, 3});
  expectPlaced(p[2], {3, 0}, {3, 0}, {0, 3});
  expectPlaced(p[3], {0, -3}, {3, 0}, {0, 3});
}

TEST(MovieLayout, TiledAndUnconnectedWallsKeepTheirShape) {
  // Two tiles of one display wall, side by side, and a camera wall.
  const WallCorners a = wall({0, 2, 0}, {2, 2, 0}, {0, 2, 1});
  const WallCorners b = wall({2, 2, 0}, {4, 2, 0}, {2, 2, 1});
  MovieWallShape camera{std::nullopt, {160, 90}, 16.0f / 9.0f};
  const auto p = unfoldWalls({shape(a), shape(b), camera});
  expectPlaced(p[0], {0, 0}, {2, 0}, {0, 1});
  expectPlaced(p[1], {2, 0}, {2, 0}, {0, 1});
  // The camera wall starts a new piece on the right, as high as what is placed.
  expectPlaced(p[2], {4, 0}, {16.0 / 9.0, 0}, {0, 1});
}

TEST(MovieLayout, AFrameOfItsOwnSizeFitsEachEyesCrossCentred) {
  const MovieLayout l = layoutMovie({shape(kFront), shape(kLeft), shape(kRight), shape(kFloor)},
                                    glm::ivec2(512, 192), MovieStereo::SideBySide);
  EXPECT_EQ(l.frame, glm::ivec2(512, 192));
  EXPECT_EQ(l.eyes, 2);
  // The cross is 9 m by 6 m; each eye's half is 256 by 192: 256 / 9 pixels a metre.
  const double s = 256.0 / 9.0, top = (192.0 - 6.0 * s) / 2.0;
  expectPlaced(l.walls[0], {3 * s, top + 3 * s}, {3 * s, 0}, {0, -3 * s});
  expectPlaced(l.walls[3], {3 * s, top + 6 * s}, {3 * s, 0}, {0, -3 * s});
  EXPECT_EQ(l.walls[0].pixels(), glm::ivec2(85, 85));
}

TEST(MovieLayout, WithoutASizeTheFinestWallSetsThePixelsAndSidesAreEven) {
  // A 3 m front drawn at 128 pixels, the floor at 64: the front's density.
  const MovieLayout l = layoutMovie({shape(kFront, {128, 128}), shape(kFloor, {64, 64})},
                                    std::nullopt, MovieStereo::Left);
  EXPECT_EQ(l.frame, glm::ivec2(128, 256));
  // One wall of odd pixels: rounded up to even, not scaled.
  const MovieLayout odd = layoutMovie({shape(kFront, {101, 101})}, std::nullopt, MovieStereo::Left);
  EXPECT_EQ(odd.frame, glm::ivec2(102, 102));
}

Image pattern(int width, int height) {
  Image image{width, height, std::vector<std::uint8_t>(std::size_t(width * height * 4))};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = &image.rgba[std::size_t((y * width + x) * 4)];
      p[0] = std::uint8_t(x * 13 + y * 7), p[1] = std::uint8_t(x * 31), p[2] = std::uint8_t(y * 53);
      p[3] = 255;
    }
  return image;
}

TEST(MovieCompositor, AWallAtItsOwnSizeIsCopiedExactly) {
  const Image image = pattern(40, 30);
  MovieCompositor c(layoutMovie({shape(wall({0, 0, 0}, {4, 0, 0}, {0, 0, 3}), {40, 30})},
                                std::nullopt, MovieStereo::Left));
  Image frame;
  c.compose({{image}}, frame);
  ASSERT_EQ(frame.width, 40);
  ASSERT_EQ(frame.height, 30);
  EXPECT_EQ(frame.rgba, image.rgba);
}

TEST(MovieCompositor, ACeilingGivenTheOtherWayRoundIsTurnedAboutTheFrontsTopEdge) {
  // Corners from the back: its upper edge meets the front's top, so unfolded
  // above the front it is turned half round; the usual ceiling is upright.
  const WallCorners turned = wall({1.5, -1.5, 3}, {-1.5, -1.5, 3}, {1.5, 1.5, 3});
  Image front = pattern(30, 30), ceiling = pattern(30, 30);
  for (std::size_t i = 0; i < ceiling.rgba.size(); i += 4)
    ceiling.rgba[i + 2] = std::uint8_t(255 - ceiling.rgba[i + 2]);
  for (const bool isTurned : {false, true}) {
    MovieCompositor c(
        layoutMovie({shape(kFront, {30, 30}), shape(isTurned ? turned : kCeiling, {30, 30})},
                    std::nullopt, MovieStereo::Left));
    Image frame;
    c.compose({{front}, {ceiling}}, frame);
    ASSERT_EQ(frame.width, 30);
    ASSERT_EQ(frame.height, 60);
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 30; ++x) {
        EXPECT_EQ(frame.at(x, 30 + y), front.at(x, y));
        EXPECT_EQ(isTurned ? frame.at(29 - x, 29 - y) : frame.at(x, y), ceiling.at(x, y))
            << x << "," << y << (isTurned ? " turned" : "");
      }
  }
}

TEST(MovieCompositor, SideBySideFramesShowEachEyeInItsHalf) {
  const Image left = pattern(20, 10), right = pattern(20, 10);
  Image rightShifted = right;
  for (std::size_t i = 0; i < rightShifted.rgba.size(); i += 4)
    rightShifted.rgba[i] = std::uint8_t(255 - rightShifted.rgba[i]);
  const Image both = [&] {  // a side-by-side wall's image: the eyes squeezed into halves
    Image b{20, 10, std::vector<std::uint8_t>(20 * 10 * 4)};
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 10; ++x)
        for (int ch = 0; ch < 4; ++ch) {
          b.rgba[std::size_t((y * 20 + x) * 4 + ch)] = left.at(x, y)[ch];
          b.rgba[std::size_t((y * 20 + 10 + x) * 4 + ch)] = rightShifted.at(x, y)[ch];
        }
    return b;
  }();
  const std::vector<Image> eyes = splitEyes(both, StereoMode::SideBySide);
  ASSERT_EQ(eyes.size(), 2u);
  EXPECT_EQ(eyes[0].at(3, 4), left.at(3, 4));
  EXPECT_EQ(eyes[1].at(3, 4), rightShifted.at(3, 4));
  MovieCompositor c(layoutMovie({shape(wall({0, 0, 0}, {1, 0, 0}, {0, 0, 1}), {10, 10})},
                                std::nullopt, MovieStereo::SideBySide));
  Image frame;
  c.compose({eyes}, frame);
  ASSERT_EQ(frame.width, 20);
  EXPECT_EQ(frame.at(3, 4), left.at(3, 4));
  EXPECT_EQ(frame.at(13, 4), rightShifted.at(3, 4));
  const std::vector<Image> topBottom = splitEyes(both, StereoMode::TopBottom);
  ASSERT_EQ(topBottom.size(), 2u);
  EXPECT_EQ(topBottom[0].height, 5);  // the left eye on top
  EXPECT_EQ(topBottom[1].at(0, 0), both.at(0, 5));
}

TEST(MovieSpec, OptionsAreCheckedAndNamed) {
  EXPECT_EQ(movieContainerFor("a/b.MP4"), MovieContainer::Mp4);
  EXPECT_EQ(movieContainerFor("b.webm"), MovieContainer::WebM);
  EXPECT_THROW(movieContainerFor("b.mkv"), Error);
  EXPECT_EQ(parseMovieSize("3840x2160"), glm::ivec2(3840, 2160));
  for (const char* bad : {"3840", "x2160", "3840x", "3841x2160", "8x8", "20000x2000", "1e3x2"})
    EXPECT_THROW(parseMovieSize(bad), Error) << bad;
  MovieSpec s;
  s.crf = 51;
  EXPECT_NO_THROW(validateMovieSpec(s));
  s.container = MovieContainer::WebM;
  s.crf = 63;
  EXPECT_NO_THROW(validateMovieSpec(s));
  s.crf = 64;
  EXPECT_THROW(validateMovieSpec(s), Error);
  s.crf.reset();
  s.fps = 0.5;
  EXPECT_THROW(validateMovieSpec(s), Error);
}

}  // namespace
}  // namespace sandstorm
