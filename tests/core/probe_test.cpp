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

TEST(Probe, AClickPicksTheSlicePlaneOrThePointNearestTheFieldsCentre) {
  ParticleState state;
  const glm::vec3 eye{0, -10, 2}, centre{1, 0, 3};
  // Looking along +y: the ray's point nearest the centre is (0, 0, 2).
  EXPECT_EQ(pickProbePoint(state, eye, {0, 5, 0}, centre), glm::vec3(0, 0, 2));
  // A centre behind the eye: the eye itself, never behind it.
  EXPECT_EQ(pickProbePoint(state, eye, {0, -1, 0}, centre), eye);
  state.slice.enabled = true;
  state.slice.origin = {0, -4, 0};
  state.slice.normal = {0, 2, 0};  // the plane y = -4, six metres ahead
  EXPECT_EQ(pickProbePoint(state, eye, {0, 1, 0}, centre), glm::vec3(0, -4, 2));
  const glm::vec3 slanted = pickProbePoint(state, eye, {1, 1, 0}, centre);
  EXPECT_NEAR(slanted.x, 6.0f, 1e-5f);
  EXPECT_NEAR(slanted.y, -4.0f, 1e-5f);
  // The plane behind the eye, or along the ray: the nearest point again.
  EXPECT_EQ(pickProbePoint(state, eye, {0, -1, 0}, centre), eye);
  EXPECT_EQ(pickProbePoint(state, eye, {0, 0, 1}, centre), glm::vec3(0, -10, 3));
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

TEST(Probe, ReadsTheFilesScalarArraysThere) {
  VectorField f = bake(Spin(), Box{{-2, -2, 0}, {2, 2, 2}}, {5, 5, 3});
  std::vector<float> t(f.pointCount());
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i)
        t[f.index(i, j, k)] = f.pointPosition(i, j, k).x - 2.0f * f.pointPosition(i, j, k).z;
  f.addScalars("temperature", t);
  PhysicsInputs in;
  in.field = &f;
  in.placement.offset = {10, 0, 0};                            // the field sits 10 m along x
  const ProbeReading r = readProbe({10.5f, 0.3f, 1.25f}, in);  // local (0.5, 0.3, 1.25)
  ASSERT_EQ(r.scalars.size(), 1u);
  EXPECT_EQ(r.scalars[0].first, "temperature");
  EXPECT_NEAR(r.scalars[0].second, 0.5f - 2.5f, 1e-5f);  // linear: trilinear is exact
}

}  // namespace
}  // namespace sandstorm
