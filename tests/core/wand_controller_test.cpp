// The wand's interactions, decided on the main context: the ray's hits (menu
// panel, emitter handles, ground), pixels on the menu wall for each stereo
// layout, grab-and-carry, the thesis's tilt throttle and joystick flying.
#include "core/tracking/wand_controller.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/sim/attribute_table.h"
#include "core/tracking/tracker_script.h"

namespace sandstorm {
namespace {

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

// The front wall of the 3 m CAVE, 480x480 pixels.
WallSpec frontWall() {
  WallSpec w;
  w.name = "front";
  w.corners = {{-1.5f, 1.5f, 0.0f}, {1.5f, 1.5f, 0.0f}, {-1.5f, 1.5f, 3.0f}};
  w.offscreenSize = {480, 480};
  return w;
}

// A tracked wand at `at` (room), pointing by yaw (90: +y) and pitch.
TrackingSample wandAt(glm::vec3 at, float yawDeg, float pitchDeg, std::uint32_t buttons = 0,
                      glm::vec2 joystick = glm::vec2(0.0f)) {
  TrackingSample s;
  s.active = s.headTracked = true;
  s.head.position = {0.0f, 0.0f, 1.7f};
  s.wand.present = s.wand.tracked = true;
  s.wand.pose = {at, bodyRotation(yawDeg, pitchDeg, 0.0f)};  // canonical axes = body axes here
  s.wand.buttons = buttons;
  s.wand.joystick = joystick;
  return s;
}

TEST(WallPixel, MapsWallCoordinatesToTheOverlaysPixels) {
  WallSpec w = frontWall();
  EXPECT_EQ(wallPixel(w, {480, 480}, {0.25f, 0.75f}), glm::vec2(120, 120));
  w.stereo = StereoMode::SideBySide;  // the overlay lies in the left half
  EXPECT_EQ(wallPixel(w, {960, 480}, {0.25f, 0.75f}), glm::vec2(120, 120));
  w.stereo = StereoMode::TopBottom;  // the left eye on top
  EXPECT_EQ(wallPixel(w, {480, 960}, {0.25f, 0.75f}), glm::vec2(120, 120));
}

TEST(WandRay, HitsWallsSpheresAndTheGround) {
  const Ray ray{{0, 0, 1.5f}, {0, 1, 0}};
  const auto wall = hitWall(ray, frontWall().corners);
  ASSERT_TRUE(wall);
  EXPECT_NEAR(wall->t, 1.5f, 1e-6f);
  EXPECT_NEAR(wall->uv.x, 0.5f, 1e-6f);
  EXPECT_NEAR(wall->uv.y, 0.5f, 1e-6f);
  EXPECT_FALSE(hitWall(Ray{{0, 0, 1.5f}, {0, -1, 0}}, frontWall().corners));
  EXPECT_FALSE(hitWall(Ray{{0, 0, 3.5f}, {0, 1, 0}}, frontWall().corners));  // above it
  EXPECT_NEAR(*hitSphere(ray, {0, 5, 1.5f}, 0.5f), 4.5f, 1e-5f);
  EXPECT_FALSE(hitSphere(ray, {1, 5, 1.5f}, 0.5f));
  // Down 45 degrees onto a flat ground 0.2 m below the room's floor through a
  // navigation that halves the world: the world's ground is at world z 0.
  Navigation nav{{0, 0, -0.2f}, 0.3f, 0.5f};
  const Ray down{{0, 0, 1.0f}, glm::normalize(glm::vec3(0, 1, -1))};
  const auto g = hitGround(down, nav, HeightMap::flat(0.0f), 20.0f);
  ASSERT_TRUE(g);
  EXPECT_NEAR(down.at(*g).z, -0.2f, 1e-4f);
  // A hill: a height map rising along x.
  const HeightMap hill({-10, -10}, {10, 10}, {3, 3}, {0, 5, 10, 0, 5, 10, 0, 5, 10});
  const Ray east{{0, 0, 6.0f}, {1, 0, 0}};
  const auto h = hitGround(east, Navigation{}, hill, 50.0f);
  ASSERT_TRUE(h);
  EXPECT_NEAR(*h, 2.0f, 1e-3f);  // height 0.5 x + 5 reaches 6 at x = 2
}

struct Fixture {
  ParticleState state;
  WandController wand{TrackingSpec{}, NavigationSpec{}};
  WandScene scene;

  Fixture() {
    state.emitters.resize(2);
    state.emitters[0].position = {0.0f, 0.0f, 0.0f};
    state.emitters[1].position = {4.0f, 0.0f, 0.0f};
    scene.state = &state;
    scene.navigation = Navigation{{-1.0f, 2.6f, 0.0f}, 0.0f, 0.35f};
  }
  // Applies the sets the way the main context would.
  WandActions step(const TrackingSample& s, float dt = 1.0f / 60.0f) {
    WandActions a = wand.update(s, scene, dt);
    for (const auto& [key, value] : a.sets)
      AttributeTable::instance().set(state, key, value);
    return a;
  }
};

TEST(WandController, PointsAtTheMenuPanelAndClicksWithTheTrigger) {
  Fixture f;
  f.scene.menu = WandMenuTarget{frontWall(), {480, 480}, {8, 8}, {388, 400}};
  // Aim at wall pixel (120, 120): u = 0.25, v = 0.75 -> room (-0.75, 1.5, 2.25).
  const glm::vec3 from{0.0f, 0.0f, 1.2f};
  const glm::vec3 to{-0.75f, 1.5f, 2.25f};
  const glm::vec3 d = glm::normalize(to - from);
  const float yaw = glm::degrees(std::atan2(d.y, d.x));
  const float pitch = glm::degrees(std::asin(d.z));
  WandActions a = f.step(wandAt(from, yaw, pitch));
  ASSERT_TRUE(a.menu);
  EXPECT_NEAR(a.menu->pixel.x, 120.0f, 0.05f);
  EXPECT_NEAR(a.menu->pixel.y, 120.0f, 0.05f);
  EXPECT_FALSE(a.menu->down);
  EXPECT_EQ(a.ray.target, WandTarget::Menu);
  expectNear(a.ray.end, to);
  a = f.step(wandAt(from, yaw, pitch, 1u));  // the trigger
  ASSERT_TRUE(a.menu);
  EXPECT_TRUE(a.menu->down);
  // Off the panel (the wall's right half): no pointer.
  a = f.step(wandAt(from, 50.0f, pitch, 1u));
  EXPECT_FALSE(a.menu);
  EXPECT_NE(a.ray.target, WandTarget::Menu);
}

TEST(WandController, GrabCarriesTheEmitterByTheWandsDisplacement) {
  Fixture f;
  // Emitter 0 (world origin) is at room (-1, 2.6, 0): aim at it from (-1, 1, 1).
  const glm::vec3 from{-1.0f, 1.0f, 1.0f};
  const glm::vec3 d = glm::normalize(glm::vec3(-1.0f, 2.6f, 0.0f) - from);
  const float yaw = glm::degrees(std::atan2(d.y, d.x)), pitch = glm::degrees(std::asin(d.z));
  WandActions a = f.step(wandAt(from, yaw, pitch));
  EXPECT_EQ(a.ray.target, WandTarget::Emitter);
  EXPECT_EQ(a.ray.emitter, 0);
  a = f.step(wandAt(from, yaw, pitch, 2u));  // the grab button (1)
  EXPECT_TRUE(a.ray.holding);
  EXPECT_TRUE(a.sets.empty());  // grabbing alone moves nothing
  const glm::vec3 move{0.3f, -0.2f, 0.5f};
  a = f.step(wandAt(from + move, yaw, pitch, 2u));
  ASSERT_EQ(a.sets.size(), 1u);
  EXPECT_EQ(a.sets[0].first, "emitter.0.position");
  // Room metres through a navigation of scale 0.35: the world moves 1/0.35 as far.
  expectNear(f.state.emitters[0].position, move / 0.35f);
  EXPECT_EQ(f.state.emitters[1].position, glm::vec3(4, 0, 0));
  // Let go: the wand moves on alone.
  f.step(wandAt(from + move, yaw, pitch, 0u));
  a = f.step(wandAt(from, yaw, pitch, 0u));
  EXPECT_TRUE(a.sets.empty());
  expectNear(f.state.emitters[0].position, move / 0.35f);
}

// The molecules' push tool: the grab button off a handle blows from half a
// metre ahead of the wand (in world coordinates) until it is let go; with the
// tool off the button does nothing of the kind.
TEST(WandController, TheGrabButtonOffAHandlePushesMoleculesWithThePushTool) {
  Fixture f;
  const glm::vec3 from{0.5f, 0.0f, 1.2f};  // pointing along +x: no handle on the ray
  WandActions a = f.step(wandAt(from, 0.0f, 0.0f, 2u));
  EXPECT_FALSE(f.state.molecules.push);  // the tool is off
  f.step(wandAt(from, 0.0f, 0.0f, 0u));
  f.state.molecules.pushTool = true;
  a = f.step(wandAt(from, 0.0f, 0.0f, 2u));
  EXPECT_TRUE(f.state.molecules.push);
  // Room (1, 0, 1.2), through a navigation of offset (-1, 2.6, 0) and scale 0.35.
  expectNear(f.state.molecules.pushPosition,
             f.scene.navigation.roomToWorld(from + glm::vec3(WandController::kPushReach, 0, 0)));
  const glm::vec3 moved = from + glm::vec3(0.0f, 0.2f, 0.0f);
  f.step(wandAt(moved, 0.0f, 0.0f, 2u));
  expectNear(f.state.molecules.pushPosition,
             f.scene.navigation.roomToWorld(moved + glm::vec3(WandController::kPushReach, 0, 0)));
  a = f.step(wandAt(moved, 0.0f, 0.0f, 0u));
  EXPECT_FALSE(f.state.molecules.push);
  // On a handle the button grabs it instead.
  const glm::vec3 d = glm::normalize(glm::vec3(-1.0f, 2.6f, 0.0f) - from);
  a = f.step(wandAt(from, glm::degrees(std::atan2(d.y, d.x)), glm::degrees(std::asin(d.z)), 2u));
  EXPECT_TRUE(a.ray.holding);
  EXPECT_FALSE(f.state.molecules.push);
}

// The rake's ends and the slice's point are handles too while they show.
TEST(WandController, GrabCarriesTheStreamlineRakeAndTheSlice) {
  Fixture f;
  f.state.streamlines.enabled = true;
  f.state.streamlines.to = {2.0f, 0.0f, 2.0f};  // room (-0.3, 2.6, 0.7)
  f.state.slice.enabled = true;
  f.state.slice.origin = {-2.0f, 0.0f, 4.0f};  // room (-1.7, 2.6, 1.4)
  // Aimed from `from` at a handle, then moved without turning (a rigid carry).
  struct Aim {
    float yaw, pitch;
  };
  auto aimAt = [&](glm::vec3 world, glm::vec3 from) {
    const glm::vec3 room = glm::vec3(f.scene.navigation.worldToRoom() * glm::vec4(world, 1.0f));
    const glm::vec3 d = glm::normalize(room - from);
    return Aim{glm::degrees(std::atan2(d.y, d.x)), glm::degrees(std::asin(d.z))};
  };
  const glm::vec3 from{0.0f, 1.0f, 1.0f};
  const glm::vec3 to = f.state.streamlines.to;
  const Aim atTo = aimAt(to, from);
  WandActions a = f.step(wandAt(from, atTo.yaw, atTo.pitch, 0u));
  EXPECT_EQ(a.ray.target, WandTarget::Emitter);
  EXPECT_EQ(a.ray.emitter, 3);  // after the two emitters and the rake's start
  f.step(wandAt(from, atTo.yaw, atTo.pitch, 2u));
  a = f.step(wandAt(from + glm::vec3(0.0f, 0.0f, 0.35f), atTo.yaw, atTo.pitch, 2u));  // up 0.35 m
  ASSERT_EQ(a.sets.size(), 1u);
  EXPECT_EQ(a.sets[0].first, "streamlines.to");
  expectNear(f.state.streamlines.to, to + glm::vec3(0.0f, 0.0f, 1.0f));  // 1 m in the world
  EXPECT_EQ(f.state.streamlines.from, StreamlineSettings{}.from);
  f.step(wandAt(from, atTo.yaw, atTo.pitch, 0u));  // let go
  const glm::vec3 origin = f.state.slice.origin;
  const Aim atOrigin = aimAt(origin, from);
  f.step(wandAt(from, atOrigin.yaw, atOrigin.pitch, 0u));
  f.step(wandAt(from, atOrigin.yaw, atOrigin.pitch, 2u));
  a = f.step(wandAt(from + glm::vec3(0.35f, 0.0f, 0.0f), atOrigin.yaw, atOrigin.pitch, 2u));
  ASSERT_EQ(a.sets.size(), 1u);
  EXPECT_EQ(a.sets[0].first, "slice.origin");
  expectNear(f.state.slice.origin, origin + glm::vec3(1.0f, 0.0f, 0.0f));
}

TEST(WandController, TiltTowardsTheUserRaisesTheThrottle) {
  Fixture f;
  f.state.helicopter.enabled = true;
  f.state.helicopter.throttle = 0.5f;
  for (int i = 0; i < 60; ++i)  // one second tilted 45 degrees up
    f.step(wandAt({0, 0, 1.2f}, 90.0f, 45.0f));
  // 0.4/s at full tilt (50 degrees), scaled by (45 - 15) / (50 - 15), in steps of 0.02.
  const float expected = 0.5f + 0.4f * 30.0f / 35.0f;
  EXPECT_NEAR(f.state.helicopter.throttle, expected, WandController::kThrottleStep);
  const float high = f.state.helicopter.throttle;
  for (int i = 0; i < 60; ++i)  // level, within the dead zone
    f.step(wandAt({0, 0, 1.2f}, 90.0f, 10.0f));
  EXPECT_EQ(f.state.helicopter.throttle, high);
  for (int i = 0; i < 60; ++i)  // away from the user: down
    f.step(wandAt({0, 0, 1.2f}, 90.0f, -45.0f));
  EXPECT_NEAR(f.state.helicopter.throttle, high - 0.4f * 30.0f / 35.0f,
              WandController::kThrottleStep);
  f.state.helicopter.wandThrottle = false;  // the menu's switch
  const float off = f.state.helicopter.throttle;
  for (int i = 0; i < 60; ++i)
    f.step(wandAt({0, 0, 1.2f}, 90.0f, 45.0f));
  EXPECT_EQ(f.state.helicopter.throttle, off);
}

TEST(WandController, TheJoystickFliesAlongTheWandAndTurnsAboutTheHead) {
  Fixture f;
  NavigationSpec speeds;
  speeds.flySpeed = 2.0f;
  speeds.turnSpeedDeg = 90.0f;
  f.wand = WandController(TrackingSpec{}, speeds);
  f.scene.navigation = Navigation{};
  Navigation n = f.scene.navigation;
  for (int i = 0; i < 30; ++i) {  // half a second forward, the wand pointing +y (and a bit down)
    const WandActions a = f.step(wandAt({0, 0, 1.2f}, 90.0f, -20.0f, 0, {0.0f, 1.0f}));
    ASSERT_TRUE(a.navigation);
    f.scene.navigation = n = *a.navigation;
  }
  expectNear(n.offset, {0.0f, -1.0f, 0.0f});  // the world moved back 1 m: the user flew 1 m
  // Turning right for a second: 90 degrees, and the point under the head stays put.
  TrackingSample s = wandAt({0, 0, 1.2f}, 90.0f, 0.0f, 0, {1.0f, 0.0f});
  s.head.position = {0.5f, 0.25f, 1.7f};
  const glm::vec3 under = n.roomToWorld({0.5f, 0.25f, 0.0f});
  for (int i = 0; i < 60; ++i) {
    const WandActions a = f.step(s);
    ASSERT_TRUE(a.navigation);
    f.scene.navigation = n = *a.navigation;
  }
  EXPECT_NEAR(n.yawRadians, glm::radians(90.0f), 1e-4f);
  expectNear(n.roomToWorld({0.5f, 0.25f, 0.0f}), under);
  // In the dead zone nothing moves.
  EXPECT_FALSE(f.step(wandAt({0, 0, 1.2f}, 90.0f, 0.0f, 0, {0.05f, -0.08f})).navigation);
}

TEST(WandController, AnUntrackedWandDrawsNothingAndLetsGo) {
  Fixture f;
  TrackingSample s = wandAt({0, 0, 1.2f}, 90.0f, 0.0f, 2u);
  s.wand.tracked = false;
  const WandActions a = f.step(s);
  EXPECT_FALSE(a.ray.visible);
  EXPECT_TRUE(a.sets.empty());
  EXPECT_EQ(f.wand.holding(), -1);
}

TEST(WandController, AStalledFrameMovesTheThrottleAndTheUserNoMoreThanATenthOfASecond) {
  Fixture f;
  f.state.helicopter.enabled = true;
  f.state.helicopter.throttle = 0.5f;
  NavigationSpec speeds;
  speeds.flySpeed = 2.0f;
  f.wand = WandController(TrackingSpec{}, speeds);
  f.step(wandAt({0, 0, 1.2f}, 90.0f, 60.0f), 3.0f);  // tilted fully up through a 3 s stall
  EXPECT_LE(f.state.helicopter.throttle, 0.5f + 0.1f * WandController::kThrottleRate + 1e-6f);
  const WandActions a = f.step(wandAt({0, 0, 1.2f}, 90.0f, 0.0f, 0, {0.0f, 1.0f}), 3.0f);
  ASSERT_TRUE(a.navigation);
  EXPECT_NEAR(glm::length(a.navigation->offset - f.scene.navigation.offset), 0.2f, 1e-4f);
}

TEST(WandController, AnOccludedWandStillFliesWhereTheHeadLooks) {
  Fixture f;
  NavigationSpec speeds;
  speeds.flySpeed = 2.0f;
  f.wand = WandController(TrackingSpec{}, speeds);
  f.scene.navigation = Navigation{};
  // The wand points +y but is hidden; the head looks along +x.
  TrackingSample s = wandAt({0, 0, 1.2f}, 90.0f, 0.0f, 0, {0.0f, 1.0f});
  s.wand.tracked = false;
  s.head.axes = bodyRotation(0.0f, 0.0f, 0.0f);
  ASSERT_GT(s.head.forward().x, 0.99f);
  Navigation n = f.scene.navigation;
  for (int i = 0; i < 30; ++i) {  // half a second at 2 m/s
    const WandActions a = f.step(s);
    EXPECT_FALSE(a.ray.visible);
    ASSERT_TRUE(a.navigation) << "the joystick of a hidden wand must still fly";
    f.scene.navigation = n = *a.navigation;
  }
  expectNear(n.offset, {-1.0f, 0.0f, 0.0f});
}

TEST(WandController, TheGroundStopsTheRay) {
  Fixture f;
  HeightMap ground = HeightMap::flat(0.0f);
  f.scene.ground = &ground;
  f.scene.navigation = Navigation{};
  f.state.emitters.clear();
  const WandActions a = f.step(wandAt({0, 0, 1.0f}, 90.0f, -45.0f));
  EXPECT_EQ(a.ray.target, WandTarget::Ground);
  expectNear(a.ray.end, {0.0f, 1.0f, 0.0f});
}

}  // namespace
}  // namespace sandstorm
