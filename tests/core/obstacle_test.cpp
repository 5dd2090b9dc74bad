// Obstacles (core/obstacles): the flow around them against potential-flow
// theory, particles kept out of them by the CPU reference, bounces against
// the restitution law, the helicopter's parts, paths and picking.
#include <gtest/gtest.h>

#include <cmath>

#include "core/config/app_config.h"
#include "core/field/wind_field.h"
#include "core/obstacles/collision_shapes.h"
#include "core/obstacles/helicopter_shape.h"
#include "core/obstacles/obstacle_path.h"
#include "core/obstacles/obstacle_physics.h"
#include "core/obstacles/obstacle_pick.h"
#include "core/sim/attribute_table.h"
#include "core/sim/particle_physics.h"
#include "core/sim/reference_simulator.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

Obstacle sphere(glm::vec3 at, float radius) {
  Obstacle o;
  o.shape = ObstacleShape::Sphere;
  o.position = at;
  o.radius = radius;
  return o;
}

Obstacle box(glm::vec3 at, glm::vec3 size) {
  Obstacle o;
  o.shape = ObstacleShape::Box;
  o.position = at;
  o.size = size;
  return o;
}

Obstacle cylinder(glm::vec3 at, float radius, float height) {
  Obstacle o;
  o.shape = ObstacleShape::Cylinder;
  o.position = at;
  o.radius = radius;
  o.height = height;
  return o;
}

// Points on a sphere of radius r about c, spread by a golden-angle spiral.
std::vector<glm::vec3> spherePoints(glm::vec3 c, float r, int n) {
  std::vector<glm::vec3> out;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, s = std::sqrt(1.0 - z * z);
    const double a = 2.39996322972865332 * i;
    out.push_back(c + r * glm::vec3(float(s * std::cos(a)), float(s * std::sin(a)), float(z)));
  }
  return out;
}

// The potential of a uniform stream U past a sphere of radius R at the origin,
// phi = U.x (1 + R^3 / (2 |x|^3)), in double; its gradient by central
// differences is the velocity potential-flow theory gives.
glm::dvec3 potentialFlow(glm::dvec3 U, double R, glm::dvec3 x) {
  const auto phi = [&](glm::dvec3 p) {
    const double r = glm::length(p);
    return glm::dot(U, p) * (1.0 + R * R * R / (2.0 * r * r * r));
  };
  const double h = 1e-5;
  glm::dvec3 g;
  for (int a = 0; a < 3; ++a) {
    glm::dvec3 e(0.0);
    e[a] = h;
    g[a] = (phi(x + e) - phi(x - e)) / (2.0 * h);
  }
  return g;
}

TEST(ObstacleFlow, ASphereInAUniformStreamIsPotentialFlow) {
  const glm::vec3 centre(1.0f, -2.0f, 1.5f), U(2.0f, 0.5f, -0.3f);
  const Obstacle o = sphere(centre, 0.7f);
  double worst = 0.0;
  for (const float r : {0.7f, 0.8f, 1.0f, 1.4f, 2.5f, 6.0f})
    for (const glm::vec3& x : spherePoints(centre, r, 200)) {
      const glm::vec3 v = flowAroundObstacles(U, x, std::span(&o, 1), true);
      const glm::dvec3 expected = potentialFlow(glm::dvec3(U), 0.7, glm::dvec3(x - centre));
      worst = std::max(worst, glm::length(glm::dvec3(v) - expected) / glm::length(glm::dvec3(U)));
    }
  EXPECT_LT(worst, 1e-4);  // float against double differences of the potential
}

TEST(ObstacleFlow, NextToEachShapeTheFlowIsTangentToItsSurface) {
  const glm::vec3 U(1.5f, -0.4f, 0.6f);
  for (const Obstacle& o : {sphere({0, 0, 1}, 0.5f), box({0, 0, 1}, {1.0f, 0.6f, 0.8f}),
                            cylinder({0, 0, 1}, 0.4f, 1.2f)}) {
    SCOPED_TRACE(int(o.shape));
    int checked = 0;
    for (const glm::vec3& p : spherePoints(o.position, 2.0f, 400)) {
      // March from outside to the surface along the ray to the centre.
      glm::vec3 x = p;
      for (int i = 0; i < 200; ++i) {
        const float d = obstacleSurface(o, x).distance;
        if (d < 1e-5f) break;
        x = x + d * glm::normalize(o.position - x);
      }
      const ObstacleSurface s = obstacleSurface(o, x);
      if (std::abs(s.distance) > 1e-4f) continue;
      const glm::vec3 v = flowAroundObstacles(U, x, std::span(&o, 1), true);
      // Relative to the stream's speed, the normal component is rounding.
      EXPECT_LT(std::abs(glm::dot(v, s.normal)), 2e-3f * glm::length(U))
          << x.x << " " << x.y << " " << x.z;
      ++checked;
    }
    EXPECT_GT(checked, 300);
  }
}

TEST(ObstacleFlow, FarFromABoxTheStreamIsUntouchedAndAMovingSphereCarriesTheAirAtItsSurface) {
  const Obstacle b = box({0, 0, 1}, {1, 1, 1});
  const glm::vec3 U(1, 2, 3);
  // The layer is the smallest half extent: 0.5 m.
  EXPECT_EQ(flowAroundObstacles(U, {0, 0, 2.01f}, std::span(&b, 1), true), U);
  EXPECT_NE(flowAroundObstacles(U, {0, 0, 1.9f}, std::span(&b, 1), true), U);
  // Still air, a sphere moving at V: at its surface the air moves with it
  // along the normal (v.n = V.n), as the kinematic boundary condition says.
  Obstacle s = sphere({0, 0, 0}, 1.0f);
  s.velocity = {3.0f, 0.0f, 0.0f};
  for (const glm::vec3& x : spherePoints({0, 0, 0}, 1.0f, 100)) {
    const glm::vec3 n = glm::normalize(x);
    const glm::vec3 v = flowAroundObstacles(glm::vec3(0.0f), x, std::span(&s, 1), true);
    EXPECT_NEAR(glm::dot(v, n), glm::dot(s.velocity, n), 1e-5f);
  }
  // A force field (the force model) is turned, not offset by the velocity.
  EXPECT_EQ(flowAroundObstacles(glm::vec3(0.0f), {0, 0, 1.5f}, std::span(&s, 1), false),
            glm::vec3(0.0f));
}

TEST(ObstacleCollision, APushedOutParticleIsOnTheSurfaceAndBouncesWithItsRestitution) {
  Obstacle b = box({0, 0, 1}, {2, 2, 2});
  b.restitution = 0.5f;
  glm::vec3 x(0.2f, 0.1f, 1.9f), v(1.0f, 0.0f, -4.0f);
  ASSERT_TRUE(pushOutOfObstacle(b, x, v, nullptr));
  EXPECT_FLOAT_EQ(x.z, 2.0f + kObstacleMargin);  // through the nearest face, the top
  EXPECT_FLOAT_EQ(x.x, 0.2f);
  EXPECT_FLOAT_EQ(v.z, 2.0f);  // -(-4) x 0.5
  EXPECT_FLOAT_EQ(v.x, 1.0f);  // the tangential part is kept
  // Already leaving (relative to a box that moves away faster): no bounce.
  b.velocity = {0, 0, -6.0f};
  x = {0.0f, 0.0f, 1.95f};
  v = {0.0f, 0.0f, -4.0f};
  ASSERT_TRUE(pushOutOfObstacle(b, x, v, nullptr));
  EXPECT_FLOAT_EQ(v.z, -4.0f);
  // Outside: untouched.
  x = {0, 0, 2.5f};
  EXPECT_FALSE(pushOutOfObstacle(b, x, v, nullptr));
}

TEST(ObstacleCollision, AParticleTheNearestPointWouldBuryLeavesUpwards) {
  // A sphere of radius 1 sunk 0.5 m into flat ground at z = 0: a particle
  // just above the ground inside it, below its centre, would go out and down
  // through the ground.
  const HeightMap ground = HeightMap::flat(0.0f);
  const Obstacle s = sphere({0, 0, 0.5f}, 1.0f);
  glm::vec3 x(0.3f, 0.0f, 0.05f), v(0.0f);
  ASSERT_TRUE(pushOutOfObstacle(s, x, v, &ground));
  EXPECT_GE(obstacleSurface(s, x).distance, 0.0f);
  EXPECT_FLOAT_EQ(x.x, 0.3f);
  EXPECT_NEAR(x.z, 0.5f + std::sqrt(1.0f - 0.09f), 2e-4f);  // the top of its column
}

// A dense cloud blown through solids: after every step of the CPU reference,
// no particle is inside any of them.
struct Cloud {
  ParticleState state;
  std::shared_ptr<VectorField> field;
};

Cloud denseWind(MotionModel motion) {
  Cloud c;
  WindParams wind;
  wind.direction = {2.0f, 0.3f, 0.0f};
  wind.power = 2.0f;
  wind.noise = 0.3f;
  c.field = std::make_shared<VectorField>(
      bake(WindField(wind), Box{{-15, -6, 0}, {15, 6, 8}}, {16, 8, 5}));
  c.state.sim.motion = motion;
  c.state.sim.maximum = 20000;
  c.state.sim.dragTime = 0.2f;
  Emitter& e = c.state.emitters[0];
  e.shape = EmitterShape::Box;
  e.position = {-3.0f, 0.0f, 1.5f};
  e.width = 0.5f;
  e.depth = 3.0f;
  e.height = 2.5f;
  e.rate = 20000.0f;
  e.lifetime = 4.0f;
  e.velocity = {2.0f, 0.0f, 0.0f};
  e.spread = 1.0f;
  return c;
}

void expectNoneInside(const ReferenceSimulator& sim, const std::vector<Obstacle>& solids,
                      int frame) {
  for (const Particle& p : sim.particles())
    for (std::size_t i = 0; i < solids.size(); ++i)
      ASSERT_GE(obstacleSurface(solids[i], p.position()).distance, 0.0f)
          << "frame " << frame << ", obstacle " << i;
}

TEST(ObstacleCollision, NoParticleIsInsideAnObstacleAfterAnyStep) {
  for (const MotionModel motion : {MotionModel::Tracer, MotionModel::Drag, MotionModel::Force}) {
    SCOPED_TRACE(int(motion));
    Cloud c = denseWind(motion);
    c.state.obstacles = {sphere({-0.5f, -0.8f, 1.5f}, 0.6f),
                         box({0.8f, 0.8f, 1.2f}, {0.6f, 0.9f, 1.5f}),
                         cylinder({2.0f, -0.5f, 1.0f}, 0.4f, 2.0f)};
    c.state.obstacles[2].flow = false;  // only bounces: particles hit it head on
    ReferenceSimulator sim(1 << 15);
    sim.setField(c.field);
    const auto ground = std::make_shared<HeightMap>(HeightMap::flat(0.0f));
    sim.setTerrain(ground);
    std::size_t peak = 0;
    for (int f = 0; f < 180; ++f) {
      // The sphere sweeps across the stream: it runs into particles too.
      c.state.obstacles[0].position.y = -0.8f + 1.6f * std::sin(0.05f * float(f));
      c.state.obstacles[0].velocity.y = 1.6f * 0.05f * 60.0f * std::cos(0.05f * float(f));
      const std::vector<std::uint32_t> counts{400};
      sim.step(SimStep{std::uint32_t(f), 1.0f / 60.0f, Seed::from(7), counts, 0.0f}, c.state);
      expectNoneInside(sim, collisionShapes(c.state, ground.get()), f);
      peak = std::max(peak, sim.particles().size());
    }
    EXPECT_GT(peak, 10000u);
  }
}

TEST(ObstacleCollision, NoParticleEndsAStepInsideTheHelicopterFlyingThroughACloud) {
  Cloud c = denseWind(MotionModel::Drag);
  c.state.emitters[0].position = {0.0f, 0.0f, 3.5f};
  c.state.emitters[0].width = 6.0f;
  c.state.emitters[0].depth = 4.0f;
  c.state.emitters[0].height = 5.0f;
  c.state.emitters[0].spread = 0.2f;
  c.state.sim.gravity = glm::vec3(0.0f);
  c.state.helicopter.enabled = true;
  c.state.helicopter.altitude = 5.0f;  // the fuselage's belly 1.6 m up
  c.state.helicopter.collideRotor = true;
  ReferenceSimulator sim(1 << 15);
  sim.setField(c.field);
  const auto ground = std::make_shared<HeightMap>(HeightMap::flat(0.0f));
  sim.setTerrain(ground);
  for (int f = 0; f < 150; ++f) {
    // 1 m a frame at rotor radius 7 m: its 12 m fuselage crosses the cloud.
    c.state.helicopter.x = -12.0f + 0.16f * float(f);
    const std::vector<std::uint32_t> counts{f < 60 ? 600u : 0u};
    sim.step(SimStep{std::uint32_t(f), 1.0f / 60.0f, Seed::from(9), counts, 0.0f}, c.state);
    const std::vector<Obstacle> solids = collisionShapes(c.state, ground.get());
    ASSERT_EQ(solids.size(), 5u);  // fuselage, boom, fin, mast, rotor disc
    expectNoneInside(sim, solids, f);
  }
  // The helicopter did pass through dust (some particles were pushed).
  EXPECT_GT(sim.particles().size(), 10000u);
}

TEST(ObstaclePath, MovesStraightBetweenKeyframesAtTheirSlopeAndLoops) {
  const ObstaclePath path({{0.0f, {0, 0, 1}}, {2.0f, {4, 0, 1}}, {3.0f, {4, 2, 1}}}, true);
  EXPECT_EQ(path.at(1.0).position, glm::vec3(2, 0, 1));
  EXPECT_EQ(path.at(1.0).velocity, glm::vec3(2, 0, 0));
  EXPECT_EQ(path.at(2.5).position, glm::vec3(4, 1, 1));
  EXPECT_EQ(path.at(2.5).velocity, glm::vec3(0, 2, 0));
  EXPECT_EQ(path.at(4.0).position, glm::vec3(2, 0, 1));  // looped: 4 - 3
  const ObstaclePath held({{1.0f, {0, 0, 0}}, {2.0f, {1, 0, 0}}}, false);
  EXPECT_EQ(held.at(5.0).position, glm::vec3(1, 0, 0));
  EXPECT_EQ(held.at(5.0).velocity, glm::vec3(0.0f));
  EXPECT_EQ(held.at(0.5).position, glm::vec3(0.5f, 0, 0));  // times count from the first key
}

TEST(ObstaclePick, TheRayFindsTheNearestObstacleAndDragsOnTheFloor) {
  std::vector<Obstacle> list{sphere({0, 5, 1}, 0.5f), box({0, 3, 1}, {1, 1, 1})};
  const auto hit = pickObstacle(list, {0, 0, 1}, {0, 1, 0});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->index, 1);
  EXPECT_NEAR(hit->point.y, 2.5f, 2e-3f);
  list[1].enabled = false;
  EXPECT_EQ(pickObstacle(list, {0, 0, 1}, {0, 1, 0})->index, 0);
  EXPECT_FALSE(pickObstacle(list, {0, 0, 1}, {1, 0, 0}));
  const auto p = dragOnFloor({0, 0, 3}, glm::normalize(glm::vec3(0, 1, -1)), 1.0f);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->y, 2.0f, 1e-5f);
  EXPECT_FALSE(dragOnFloor({0, 0, 3}, {0, 1, 0}, 1.0f));
  EXPECT_FALSE(dragOnFloor({0, 0, 3}, {0, 0, 1}, 1.0f));  // the plane is behind
}

TEST(HelicopterShape, TheSolidPartsAreTheDrawnBodyAndTheRotorDiscOnlyWhenAsked) {
  HelicopterSettings s;
  s.enabled = true;
  s.x = 3.0f;
  s.altitude = 10.0f;
  const HeightMap ground = HeightMap::flat(2.0f);
  EXPECT_EQ(helicopterHub(s, &ground), glm::vec3(3, 0, 12));
  EXPECT_EQ(helicopterObstacles(s, 7.0f, &ground).size(), 4u);
  s.collideRotor = true;
  const std::vector<Obstacle> all = helicopterObstacles(s, 7.0f, &ground);
  ASSERT_EQ(all.size(), 5u);
  EXPECT_EQ(all.back().shape, ObstacleShape::Cylinder);
  EXPECT_FLOAT_EQ(all.back().radius, 7.0f);
  for (const Obstacle& o : all)
    EXPECT_FALSE(o.flow);  // the wash is in the field already
  s.collide = false;
  EXPECT_TRUE(helicopterObstacles(s, 7.0f, &ground).empty());
}

const std::string kWall =
    "[[wall]]\nname = \"w\"\ncamera = {position = [0, -5, 1.7], target = [0, 0, 1]}\noffscreen = "
    "{size = [64, 48]}\n";

std::string configError(const std::string& text) {
  try {
    parseConfig(kWall + text, "obstacles.toml");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ObstacleConfig, ObstaclesAndTheirPathsLoadAndBadOnesNameTheLineAndKey) {
  const AppConfig c = parseConfig(kWall + R"(
[[obstacle]]
shape = "sphere"
position = [1, 2, 0.5]
radius = 0.5
path = [{time = 0, position = [1, 2, 0.5]}, {time = 4, position = [-1, 2, 0.5]}]
loop = false

[[obstacle]]
shape = "box"
size = [1, 2, 3]
restitution = 0.9
flow = false
)",
                                  "obstacles.toml");
  ASSERT_EQ(c.particles.obstacles.size(), 2u);
  EXPECT_EQ(c.particles.obstacles[0].position, glm::vec3(1, 2, 0.5f));
  EXPECT_EQ(c.particles.obstacles[1].shape, ObstacleShape::Box);
  EXPECT_EQ(c.particles.obstacles[1].size, glm::vec3(1, 2, 3));
  EXPECT_FALSE(c.particles.obstacles[1].flow);
  ASSERT_EQ(c.obstaclePaths.size(), 2u);
  EXPECT_EQ(c.obstaclePaths[0].keys().size(), 2u);
  EXPECT_FALSE(c.obstaclePaths[0].loops());
  EXPECT_TRUE(c.obstaclePaths[1].empty());

  EXPECT_EQ(configError("[[obstacle]]\nshape = \"cone\"\n"),
            "obstacles.toml:6: attribute 'obstacle.0.shape': 'cone' is not one of: sphere, box, "
            "cylinder");
  EXPECT_NE(configError("[[obstacle]]\nradius = -1\n").find("obstacles.toml:6: obstacle.0.radius"),
            std::string::npos);
  EXPECT_NE(configError("[[obstacle]]\nwidth = 1\n").find("unknown attribute 'obstacle.0.width'"),
            std::string::npos);
  EXPECT_NE(configError("[[obstacle]]\npath = [{time = 1, position = [0, 0, 0]}, {time = 1, "
                        "position = [1, 0, 0]}]\n")
                .find("obstacle.0.path[].time: expected times that increase"),
            std::string::npos);
  EXPECT_NE(configError("[[obstacle]]\npath = [{time = 0, position = [0, 0, 0]}, {time = 1, "
                        "position = [0, 1e9, 0]}]\n")
                .find("obstacle.0.path[].position: expected metres within"),
            std::string::npos);
  EXPECT_NE(configError("[[obstacle]]\npath = [{time = 1, position = [0, 0, 0]}]\n")
                .find("a path needs at least two keyframes"),
            std::string::npos);
  std::string nine;
  for (int i = 0; i < 9; ++i)
    nine += "[[obstacle]]\n";
  EXPECT_NE(configError(nine).find("at most 8 obstacles"), std::string::npos);
}

TEST(ObstacleAttributes, EachObstacleIsInTheTableAndAMissingOneIsNamed) {
  const AttributeTable& table = AttributeTable::instance();
  ParticleState s;
  s.obstacles.resize(2);
  table.set(s, "obstacle.1.radius", 2.0f);
  EXPECT_FLOAT_EQ(s.obstacles[1].radius, 2.0f);
  EXPECT_EQ(table.set(s, "obstacle.0.restitution", 3.0f).applied, AttributeValue(1.0f));
  try {
    table.set(s, "obstacle.2.radius", 1.0f);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("there is no obstacle 2 (there are 2"), std::string::npos);
  }
  EXPECT_THROW(table.lookup("obstacle.8.radius"), Error);
  EXPECT_THROW(table.lookup("obstacle.x.radius"), Error);
  EXPECT_NE(table.describe(s).find("obstacle.1.radius=2\n"), std::string::npos);
}

}  // namespace
}  // namespace sandstorm
