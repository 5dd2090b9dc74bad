// Off-axis projection (Kooima) against frusta worked out by hand, and the
// defining property: a wall's corners project onto the image's corners.
#include "core/cave/wall.h"

#include <gtest/gtest.h>

#include "core/cave/viewer.h"
#include "core/cave/wall_views.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// The thesis's four-wall CAVE: 3 m walls, z up, the viewer facing +y.
const WallCorners kFront{{-1.5f, 1.5f, 0.0f}, {1.5f, 1.5f, 0.0f}, {-1.5f, 1.5f, 3.0f}};
const WallCorners kLeft{{-1.5f, -1.5f, 0.0f}, {-1.5f, 1.5f, 0.0f}, {-1.5f, -1.5f, 3.0f}};
const WallCorners kFloor{{-1.5f, -1.5f, 0.0f}, {1.5f, -1.5f, 0.0f}, {-1.5f, 1.5f, 0.0f}};

void expectFrustum(const Frustum& f, float l, float r, float b, float t) {
  EXPECT_NEAR(f.left, l, 1e-6f);
  EXPECT_NEAR(f.right, r, 1e-6f);
  EXPECT_NEAR(f.bottom, b, 1e-6f);
  EXPECT_NEAR(f.top, t, 1e-6f);
}

TEST(OffAxis, HeadInTheCentreSeesASymmetricFrustum) {
  // Eye 1.5 m from the front wall at mid-height: extents +-1.5 m scaled by near / 1.5.
  expectFrustum(offAxisFrustum(kFront, {0.0f, 0.0f, 1.5f}, 0.1f, 100.0f), -0.1f, 0.1f, -0.1f, 0.1f);
}

TEST(OffAxis, HeadOffCentreSeesASkewedFrustum) {
  // Eye at (0.5, 0.5, 1.0): 1 m from the front wall; the wall spans x - 0.5 in [-2, 1]
  // and z - 1 in [-1, 2]; scaled by near / 1 = 0.1.
  expectFrustum(offAxisFrustum(kFront, {0.5f, 0.5f, 1.0f}, 0.1f, 100.0f), -0.2f, 0.1f, -0.1f, 0.2f);
  // The same eye and the floor, 1 m below: x - 0.5 in [-2, 1], y - 0.5 in [-2, 1].
  expectFrustum(offAxisFrustum(kFloor, {0.5f, 0.5f, 1.0f}, 0.1f, 100.0f), -0.2f, 0.1f, -0.2f, 0.1f);
  // The left wall, 2 m away: its right is +y (y - 0.5 in [-2, 1]), its up +z.
  expectFrustum(offAxisFrustum(kLeft, {0.5f, 0.5f, 1.0f}, 0.1f, 100.0f), -0.1f, 0.05f, -0.05f,
                0.1f);
}

glm::vec3 ndc(const View& v, const glm::vec3& p) {
  const glm::vec4 c = v.projection * v.view * glm::vec4(p, 1.0f);
  return glm::vec3(c) / c.w;
}

TEST(OffAxis, WallCornersLandOnTheImageCorners) {
  for (const glm::vec3 eye :
       {glm::vec3(0, 0, 1.7f), glm::vec3(-1.2f, 0.9f, 0.4f), glm::vec3(1, -1, 2.5f)}) {
    for (const WallCorners& w : {kFront, kLeft, kFloor}) {
      const View v = offAxisView(w, eye, 0.05f, 50.0f);
      const glm::vec3 ll = ndc(v, w.lowerLeft), ur = ndc(v, w.upperRight());
      const glm::vec3 lr = ndc(v, w.lowerRight), ul = ndc(v, w.upperLeft);
      EXPECT_NEAR(ll.x, -1.0f, 1e-4f);
      EXPECT_NEAR(ll.y, -1.0f, 1e-4f);
      EXPECT_NEAR(ur.x, 1.0f, 1e-4f);
      EXPECT_NEAR(ur.y, 1.0f, 1e-4f);
      EXPECT_NEAR(lr.x, 1.0f, 1e-4f);
      EXPECT_NEAR(lr.y, -1.0f, 1e-4f);
      EXPECT_NEAR(ul.x, -1.0f, 1e-4f);
      EXPECT_NEAR(ul.y, 1.0f, 1e-4f);
    }
  }
}

TEST(OffAxis, APointOnTheSharedEdgeProjectsOntoBothWallsEdges) {
  // The seam between the left and front walls is the line x = -1.5, y = 1.5.
  // Any point on the ray from the eye through a point of that edge lands on
  // the right edge of the left wall and the left edge of the front wall, at
  // the same height.
  const glm::vec3 eye(0.3f, -0.2f, 1.6f);
  const glm::vec3 edge(-1.5f, 1.5f, 2.1f);
  const glm::vec3 beyond = eye + 2.7f * (edge - eye);
  const glm::vec3 onFront = ndc(offAxisView(kFront, eye, 0.05f, 50.0f), beyond);
  const glm::vec3 onLeft = ndc(offAxisView(kLeft, eye, 0.05f, 50.0f), beyond);
  EXPECT_NEAR(onFront.x, -1.0f, 1e-4f);
  EXPECT_NEAR(onLeft.x, 1.0f, 1e-4f);
  EXPECT_NEAR(onFront.y, onLeft.y, 1e-4f);
  EXPECT_NEAR(onFront.y, 2.0f * 2.1f / 3.0f - 1.0f,
              1e-4f);  // the edge point's height on the 3 m wall
}

TEST(OffAxis, RejectsCornersThatAreNotARectangle) {
  WallCorners skew = kFront;
  skew.upperLeft.x += 0.2f;
  EXPECT_THROW(validateWall(skew, "test"), Error);
  WallCorners flat = kFront;
  flat.upperLeft = flat.lowerLeft;
  EXPECT_THROW(validateWall(flat, "test"), Error);
  EXPECT_NO_THROW(validateWall(kLeft, "test"));
}

TEST(WallViews, StereoEyesSitAlongTheHeadsRightVector) {
  WallSpec wall;
  wall.corners = kFront;
  wall.stereo = StereoMode::SideBySide;
  Viewer viewer;
  viewer.head.position = {0, 0, 1.7f};
  viewer.head.right = {1, 0, 0};
  viewer.head.eyeSeparation = 0.064f;
  const std::vector<View> views = wallViews(wall, viewer, 1.0f, 0.05f, 50.0f);
  ASSERT_EQ(views.size(), 2u);
  EXPECT_NEAR(views[0].eye.x, -0.032f, 1e-6f);
  EXPECT_NEAR(views[1].eye.x, 0.032f, 1e-6f);
}

TEST(WallViews, NavigationMovesTheWorldNotTheRoom) {
  WallSpec wall;
  wall.corners = kFront;
  Viewer viewer;
  viewer.head.position = {0, 0, 1.5f};
  viewer.navigation.offset = {0.0f, 3.0f, 0.0f};
  viewer.navigation.scale = 0.5f;
  const View v = wallViews(wall, viewer, 1.0f, 0.05f, 50.0f)[0];
  // World point (0, 0, 3) sits in the room at (0, 3, 1.5): straight ahead of the eye.
  const glm::vec3 p = ndc(v, {0.0f, 0.0f, 3.0f});
  EXPECT_NEAR(p.x, 0.0f, 1e-5f);
  EXPECT_NEAR(p.y, 0.0f, 1e-5f);
  // Billboards face the eye in world coordinates.
  EXPECT_NEAR(glm::distance(v.eye, glm::vec3(0.0f, -6.0f, 3.0f)), 0.0f, 1e-5f);
}

TEST(HeadTrackers, ScriptedHeadInterpolatesAndLoops) {
  HeadSpec spec;
  spec.mode = HeadMode::Scripted;
  spec.path = {{0.0f, {0, 0, 1}}, {2.0f, {2, 0, 1}}};
  spec.loop = true;
  const auto tracker = makeHeadTracker(spec);
  EXPECT_NEAR(tracker->pose(0.5).position.x, 0.5f, 1e-6f);
  EXPECT_NEAR(tracker->pose(2.5).position.x, 0.5f, 1e-6f);  // looped
  spec.loop = false;
  EXPECT_NEAR(makeHeadTracker(spec)->pose(7.0).position.x, 2.0f, 1e-6f);
}

TEST(HeadTrackers, DesktopHeadWalksWhereItFaces) {
  DesktopHead head(HeadPose{}, glm::radians(90.0f));  // facing +y
  head.move(1.0f, 0.0f, 0.0f);
  EXPECT_NEAR(head.pose(0).position.y, 1.0f, 1e-6f);
  head.turn(glm::radians(90.0f));  // now facing -x
  head.move(1.0f, 0.0f, 0.0f);
  EXPECT_NEAR(head.pose(0).position.x, -1.0f, 1e-5f);
  EXPECT_NEAR(head.pose(0).right.y, 1.0f, 1e-5f);  // facing -x, the right hand points to +y
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// Distance from point p to the line through the ray.
float offRay(const WorldRay& r, const glm::vec3& p) {
  return glm::length(glm::cross(p - r.origin, r.direction));
}

// The defining property: the ray through a point of a wall's image passes
// through that point of the wall, from the eye drawn there.
TEST(WallClickRay, PassesThroughTheClickedPointOfTheWall) {
  WallSpec wall;
  wall.corners = kFront;
  Viewer viewer;
  viewer.head.position = {0.3f, -0.2f, 1.2f};
  viewer.head.eyeSeparation = 0.1f;
  viewer.navigation.scale = 0.5f;
  viewer.navigation.offset = {1.0f, 0.0f, 0.0f};
  viewer.navigation.yawRadians = 0.4f;
  // at (0.25, 0.2): a quarter from the left, a fifth from the top.
  const glm::vec3 room = kFront.lowerLeft + 0.25f * (kFront.lowerRight - kFront.lowerLeft) +
                         0.8f * (kFront.upperLeft - kFront.lowerLeft);
  const glm::vec3 world = viewer.navigation.roomToWorld(room);
  const WorldRay mono = wallClickRay(wall, viewer, {0.25f, 0.2f}, 1.0f, 0.1f, 100.0f);
  EXPECT_NEAR(glm::length(mono.origin - viewer.navigation.roomToWorld(viewer.head.position)), 0.0f,
              1e-5f);
  EXPECT_LT(offRay(mono, world), 1e-4f);
  // Side by side: the same point of the right half is seen from the right eye.
  wall.stereo = StereoMode::SideBySide;
  const WorldRay right = wallClickRay(wall, viewer, {0.625f, 0.2f}, 2.0f, 0.1f, 100.0f);
  EXPECT_NEAR(glm::length(right.origin - viewer.navigation.roomToWorld(viewer.head.rightEye())),
              0.0f, 1e-5f);
  EXPECT_LT(offRay(right, world), 1e-4f);
  // A camera wall: the image's centre lies on the line to the target.
  WallSpec camera;
  camera.camera = CameraSpec{};
  camera.camera->position = {0, -8, 2};
  camera.camera->target = {1, 0, 3};
  const WorldRay centre = wallClickRay(camera, Viewer{}, {0.5f, 0.5f}, 1.5f, 0.1f, 100.0f);
  EXPECT_LT(offRay(centre, camera.camera->target), 1e-4f);
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// Each eye's part of a wall's image (GL viewports, y up): the halves of a
// side-by-side image (left eye on the left) and a top-bottom one (left eye on
// top); the whole image otherwise.
TEST(EyeViewports, SplitImagesHaveAHalfAnEye) {
  using V = std::vector<glm::ivec4>;
  EXPECT_EQ(eyeViewports(StereoMode::SideBySide, {1920, 1080}),
            (V{{0, 0, 960, 1080}, {960, 0, 960, 1080}}));
  EXPECT_EQ(eyeViewports(StereoMode::TopBottom, {1920, 1080}),
            (V{{0, 540, 1920, 540}, {0, 0, 1920, 540}}));
  for (StereoMode m : {StereoMode::Mono, StereoMode::QuadBuffer, StereoMode::Anaglyph,
                       StereoMode::LeftEye, StereoMode::RightEye})
    EXPECT_EQ(eyeViewports(m, {640, 480}), (V{{0, 0, 640, 480}}));
}

// The menu is laid out for one eye's image and drawn into each: the mouse over
// either copy points at the same widget.
TEST(EyeViewports, APointOverEitherEyesHalfFindsTheSamePlaceInTheEyesImage) {
  const glm::vec2 image(1920.0f, 1080.0f);
  EXPECT_EQ(eyeImageSize(StereoMode::SideBySide, image), glm::vec2(960.0f, 1080.0f));
  EXPECT_EQ(eyeImageSize(StereoMode::TopBottom, image), glm::vec2(1920.0f, 540.0f));
  EXPECT_EQ(eyeImageSize(StereoMode::Anaglyph, image), image);
  // Side by side: the left eye on the left half, the right eye on the right.
  EXPECT_EQ(pointInEyeImage(StereoMode::SideBySide, image, {100.0f, 700.0f}),
            glm::vec2(100.0f, 700.0f));
  EXPECT_EQ(pointInEyeImage(StereoMode::SideBySide, image, {1060.0f, 700.0f}),
            glm::vec2(100.0f, 700.0f));
  EXPECT_EQ(pointInEyeImage(StereoMode::SideBySide, image, {960.0f, 0.0f}), glm::vec2(0.0f));
  // Top-bottom, y down: the left eye on top.
  EXPECT_EQ(pointInEyeImage(StereoMode::TopBottom, image, {1500.0f, 30.0f}),
            glm::vec2(1500.0f, 30.0f));
  EXPECT_EQ(pointInEyeImage(StereoMode::TopBottom, image, {1500.0f, 570.0f}),
            glm::vec2(1500.0f, 30.0f));
  for (StereoMode m : {StereoMode::Mono, StereoMode::QuadBuffer, StereoMode::Anaglyph})
    EXPECT_EQ(pointInEyeImage(m, image, {1500.0f, 900.0f}), glm::vec2(1500.0f, 900.0f));
}

}  // namespace
}  // namespace sandstorm
