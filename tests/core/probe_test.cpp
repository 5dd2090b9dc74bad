// The probe's point (the wand's ray on the slice plane, or along the ray, or
// the attribute) and what it reads, worked out by hand.
#include "core/flow/probe.h"

#include <gtest/gtest.h>

#include "core/field/analytic_field.h"

namespace sandstorm {
namespace {

struct Spin final : AnalyticField {
  glm::vec3 evaluate(const glm::vec3& p) const override { return {-p.y, p.x, 0.0f}; }
};

TEST(Probe, FollowsTheWandToTheSlicePlaneOrAlongItsRay) {
  ParticleState state;
  state.probe.enabled = true;
  state.probe.position = {1, 2, 3};
  WandRay wand;
  Navigation nav;                                               // the world is the room
  EXPECT_EQ(probePoint(state, wand, nav), glm::vec3(1, 2, 3));  // no wand: the attribute
  wand.visible = true;
  wand.origin = {0, 0, 1};
  wand.end = {0, 4, 1};  // pointing along +y
  state.probe.reach = 1.5f;
  EXPECT_EQ(probePoint(state, wand, nav), glm::vec3(0, 1.5f, 1));
  state.slice.enabled = true;
  state.slice.origin = {0, 3, 0};
  state.slice.normal = {0, 1, 0};  // the plane y = 3
  EXPECT_EQ(probePoint(state, wand, nav), glm::vec3(0, 3, 1));
  // Navigation: the world shrunk by 2 and moved by (0, 1, 0) in the room.
  nav.scale = 0.5f;
  nav.offset = {0, 1, 0};
  state.slice.origin = {0, 2, 0};  // world y = 2 is room y = 2
  const auto p = probePoint(state, wand, nav);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->y, 2.0f, 1e-5f);  // world
  EXPECT_NEAR(p->z, 2.0f, 1e-5f);  // room z = 1 is world z = 2
  state.probe.enabled = false;
  EXPECT_FALSE(probePoint(state, wand, nav));
}

TEST(Probe, ReadsTheFieldAsTheParticlesFeelIt) {
  const VectorField f = bake(Spin(), Box{{-2, -2, 0}, {2, 2, 2}}, {5, 5, 3});
  PhysicsInputs in;
  in.field = &f;
  in.settings.fieldStrength = 3.0f;
  const ProbeReading r = readProbe({1, 0, 1}, in);
  EXPECT_TRUE(r.inside);
  EXPECT_NEAR(r.velocity.y, 3.0f, 1e-5f);
  EXPECT_NEAR(r.speed, 3.0f, 1e-5f);
  EXPECT_FALSE(readProbe({5, 0, 1}, in).inside);
}

}  // namespace
}  // namespace sandstorm
