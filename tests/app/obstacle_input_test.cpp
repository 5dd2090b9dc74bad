// The obstacles' movers on the main thread: ObstacleDriver plays scripted
// paths on simulated time and gives way to a hand; ObstacleDrag grabs an
// obstacle with a ray and slides it along the floor.
#include <gtest/gtest.h>

#include "app/molecule_push.h"
#include "app/obstacle_drag.h"
#include "app/obstacle_driver.h"

namespace sandstorm {
namespace {

MainContext mainWithSphere(glm::vec3 at) {
  ParticleState s;
  Obstacle o;
  o.position = at;
  o.radius = 0.5f;
  s.obstacles.push_back(o);
  MainContext::Options options;
  options.fixedDt = 0.25f;
  return MainContext(s, FieldUpdate{}, options);
}

TEST(ObstacleDriver, MovesAlongThePathOnSimulatedTimeAndGivesWayToAHand) {
  MainContext main = mainWithSphere({0, 0, 1});
  ObstacleDriver driver({ObstaclePath({{0.0f, {0, 0, 1}}, {2.0f, {4, 0, 1}}}, false)});
  driver.start(main);
  for (int f = 0; f < 4; ++f)
    driver.update(main, main.next());
  // 4 frames of 0.25 s: the packet of frame 4 will carry t = 1 s.
  main.next();
  EXPECT_EQ(main.state().obstacles[0].position, glm::vec3(2, 0, 1));
  EXPECT_EQ(main.state().obstacles[0].velocity, glm::vec3(2, 0, 0));
  // Paused: time stands still, so does the sphere.
  main.set("sim.paused", true);
  driver.update(main, main.next());
  const glm::vec3 held = main.pendingState().obstacles[0].position;
  driver.update(main, main.next());
  EXPECT_EQ(main.pendingState().obstacles[0].position, held);
  main.set("sim.paused", false);
  driver.update(main, main.next());
  // A hand moves it: the path lets go, and it rests where it was put.
  main.set("obstacle.0.position", glm::vec3(-3, 1, 1));
  driver.update(main, main.next());
  driver.update(main, main.next());
  main.next();
  EXPECT_FALSE(main.state().obstacles[0].path);
  EXPECT_EQ(main.state().obstacles[0].position, glm::vec3(-3, 1, 1));
  EXPECT_EQ(main.state().obstacles[0].velocity, glm::vec3(0.0f));
}

TEST(ObstacleDrag, APressOnTheSphereGrabsItAndTheDragSlidesItAlongTheFloor) {
  MainContext main = mainWithSphere({0, 5, 1});
  ObstacleDrag drag;
  // A ray that misses grabs nothing.
  EXPECT_FALSE(drag.pick(main.pendingState(), WorldRay{{0, 0, 1}, {1, 0, 0}}));
  // Straight at the sphere from the eye at (0, 0, 1): grabbed at (0, 4.5, 1).
  ASSERT_TRUE(drag.pick(main.pendingState(), WorldRay{{0, 0, 1}, {0, 1, 0}}));
  EXPECT_TRUE(drag.holding());
  // The cursor's ray from higher up now meets the grab's plane (z = 1) at
  // (1, 4.5, 1): the sphere follows, 1 m along x, its height kept.
  const glm::vec3 from(0, 0, 2);
  const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, 4.5f, 1.0f) - from);
  drag.drag(main, WorldRay{from, direction}, 0.5f, false);
  main.next();
  const Obstacle o = main.state().obstacles[0];
  EXPECT_FALSE(o.path);
  EXPECT_FLOAT_EQ(o.position.z, 1.0f);
  EXPECT_NEAR(o.position.x, 1.0f, 1e-3f);
  EXPECT_NEAR(o.position.y, 5.0f, 2e-3f);
  EXPECT_NEAR(o.velocity.x, 2.0f, 1e-2f);  // 1 m in 0.5 s
  drag.drag(main, WorldRay{from, direction}, 0.5f, true);
  main.next();
  EXPECT_EQ(main.state().obstacles[0].velocity, glm::vec3(0.0f));
  EXPECT_FALSE(drag.holding());
}

// The field editor's primitives drag the same way: a press within 0.25 m of
// one's ball grabs it (nearer than the sphere behind it), the drag slides it.
TEST(ObstacleDrag, APressNearAPrimitiveGrabsItBeforeTheObstacleBehind) {
  MainContext main = mainWithSphere({0, 5, 1});
  main.set("primitive.2.kind", std::string("vortex"));
  main.set("primitive.2.position", glm::vec3(0.1f, 3.0f, 1.0f));
  main.next();
  ObstacleDrag drag;
  ASSERT_TRUE(drag.pick(main.pendingState(), WorldRay{{0, 0, 1}, {0, 1, 0}}));
  const glm::vec3 from(0, 0, 2);
  drag.drag(main, WorldRay{from, glm::normalize(glm::vec3(-1.0f, 3.0f, 1.0f) - from)}, 0.5f, true);
  main.next();
  const glm::vec3 moved = main.state().primitives[2].position;
  EXPECT_NEAR(moved.x, -1.0f + 0.1f, 1e-3f);  // the grabbed point's offset kept
  EXPECT_FLOAT_EQ(moved.z, 1.0f);
  EXPECT_EQ(main.state().obstacles[0].position, glm::vec3(0, 5, 1));  // the sphere stayed
  EXPECT_FALSE(drag.holding());
  // Emptied, it is no longer there to grab: the press takes the sphere.
  main.set("primitive.2.kind", std::string("none"));
  main.next();
  ASSERT_TRUE(drag.pick(main.pendingState(), WorldRay{{0, 0, 1}, {0, 1, 0}}));
  drag.drag(main, WorldRay{{0, 0, 1}, {0, 1, 0}}, 0.5f, true);
}

// With molecules.push_tool on, a left press starts a push at the cursor's
// ray nearest the field's centre, the drag moves it, the release stops it.
TEST(MoleculePush, APressPushesWhereTheCursorPointsUntilReleased) {
  MainContext main = mainWithSphere({0, 5, 1});
  MoleculePush push;
  const glm::vec3 centre(0, 3, 1);
  EXPECT_FALSE(push.press(main, WorldRay{{0, 0, 1}, {0, 1, 0}}, centre));  // the tool is off
  main.set("molecules.push_tool", true);
  ASSERT_TRUE(push.press(main, WorldRay{{0, 0, 1}, {0, 1, 0}}, centre));
  main.next();
  EXPECT_TRUE(main.state().molecules.push);
  EXPECT_EQ(main.state().molecules.pushPosition, glm::vec3(0, 3, 1));
  push.drag(main, WorldRay{{1, 0, 1}, {0, 1, 0}}, centre, false);
  main.next();
  EXPECT_EQ(main.state().molecules.pushPosition, glm::vec3(1, 3, 1));
  push.drag(main, WorldRay{{1, 0, 1}, {0, 1, 0}}, centre, true);
  main.next();
  EXPECT_FALSE(main.state().molecules.push);
  EXPECT_FALSE(push.holding());
  // Never behind the eye.
  EXPECT_EQ(MoleculePush::pushPoint(WorldRay{{0, 0, 0}, {0, -1, 0}}, centre), glm::vec3(0.0f));
}

}  // namespace
}  // namespace sandstorm
