// Tracking on the main context: the tracker's room mapped to Sandstorm's
// (millimetres to metres, axes, the eyes' offset), the bodies' axes made
// canonical, and the sampler's hold of the last pose when measurements stop.
#include <gtest/gtest.h>

#include <cmath>

#include "core/tracking/ipv4_address.h"
#include "core/tracking/tracker_calibration.h"
#include "core/tracking/tracking_sampler.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr float kEps = 1e-5f;

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = kEps) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

glm::mat3 yawed(float degrees) {  // about z
  const float a = glm::radians(degrees);
  return glm::mat3(std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a), 0, 0, 0, 1);
}

TrackerFrame frameWith(glm::vec3 headMm, glm::mat3 headRotation) {
  TrackerFrame f;
  f.frame = 100;
  f.bodies.push_back({0, 1.0f, headMm, headRotation});
  TrackedFlystick s;
  s.position = {100.0f, 500.0f, 1200.0f};
  s.buttonCount = 6;
  s.buttons = 1;
  s.controllerCount = 2;
  s.controllers = {0.5f, -0.25f};
  f.flysticks.push_back(s);
  return f;
}

TEST(Ipv4Address, DottedQuadsOnly) {
  EXPECT_EQ(parseIpv4("192.168.0.20"), 0xC0A80014u);
  EXPECT_EQ(parseIpv4("0.0.0.0"), 0u);
  EXPECT_EQ(parseIpv4("255.255.255.255"), 0xFFFFFFFFu);
  for (const char* bad : {"", "1.2.3", "1.2.3.4.", "256.0.0.1", " 1.2.3.4", "1.2.3.4 ", "01.2.3.4",
                          "1.2.3.4x", "1..3.4", "-1.2.3.4", "1234.1.1.1", "host.example"})
    EXPECT_FALSE(parseIpv4(bad)) << bad;
  EXPECT_EQ(formatIpv4(0xC0A80014u), "192.168.0.20");
  EXPECT_EQ(parseIpv4(formatIpv4(0x7F000002u)), 0x7F000002u);
  EXPECT_TRUE(isMulticast(*parseIpv4("239.255.0.1")));
  EXPECT_FALSE(isMulticast(*parseIpv4("10.0.0.1")));
}

TEST(TrackerCalibration, MillimetresBecomeRoomMetres) {
  const TrackerCalibration c{TrackingSpec{}};
  const auto head = c.head(frameWith({1000.0f, -500.0f, 1700.0f}, glm::mat3(1.0f)));
  ASSERT_TRUE(head);
  expectNear(head->position, {1.0f, -0.5f, 1.7f});
  // Defaults: a body calibrated facing +y: right +x, forward +y, up +z.
  expectNear(head->right(), {1, 0, 0});
  expectNear(head->forward(), {0, 1, 0});
  expectNear(head->up(), {0, 0, 1});
}

TEST(TrackerCalibration, AYUpTrackerRoomIsTurnedAndMoved) {
  // ART's "powerwall" room: y up, z towards the viewer. rotation_deg [90, 0, 0]
  // turns its y onto the room's z (and its z onto -y); the origin sits 1.5 m ahead.
  TrackingSpec spec;
  const float a = glm::radians(90.0f);
  spec.rotation = glm::mat3(1, 0, 0, 0, std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a));
  spec.offset = {0.0f, 1.5f, 0.0f};
  const TrackerCalibration c(spec);
  expectNear(c.toRoom({0.0f, 1700.0f, 500.0f}), {0.0f, 1.0f, 1.7f});
  // A head looking down the tracker's -z (towards the screen) looks along the room's +y.
  TrackingSpec axes = spec;
  axes.headRight = {1, 0, 0};
  axes.headUp = {0, 1, 0};  // the body calibrated in that y-up room
  const auto head = TrackerCalibration(axes).head(frameWith({0, 1700, 500}, glm::mat3(1.0f)));
  ASSERT_TRUE(head);
  expectNear(head->forward(), {0, 1, 0});
  expectNear(head->up(), {0, 0, 1});
}

TEST(TrackerCalibration, TheEyesSitAtTheirOffsetInTheGlassesAxes) {
  TrackingSpec spec;
  spec.eyeOffset = {0.0f, 0.08f, -0.05f};  // 8 cm ahead of the marker tree, 5 cm below
  const TrackerCalibration c(spec);
  const auto head = c.head(frameWith({0.0f, 0.0f, 1800.0f}, yawed(90.0f)));  // facing -x
  ASSERT_TRUE(head);
  expectNear(head->position, {-0.08f, 0.0f, 1.75f});
  expectNear(head->right(), {0, 1, 0});
  expectNear(head->forward(), {-1, 0, 0});
}

TEST(TrackerCalibration, BodyAxesOfAnyCalibrationBecomeCanonical) {
  TrackingSpec spec;
  spec.headRight = {0, 0, -1};  // glasses calibrated with z to the left and y up
  spec.headUp = {0, 1, 0};
  spec.wandForward = {0, 0, -1};  // a wand pointing along its -z
  spec.wandUp = {0, 1, 0};
  const TrackerCalibration c(spec);
  const auto head = c.head(frameWith({0, 0, 0}, glm::mat3(1.0f)));
  ASSERT_TRUE(head);
  expectNear(head->right(), {0, 0, -1});
  expectNear(head->up(), {0, 1, 0});
  expectNear(glm::cross(head->right(), head->forward()), head->up());  // right-handed
  const auto wand = c.wand(frameWith({0, 0, 0}, glm::mat3(1.0f)));
  ASSERT_TRUE(wand);
  expectNear(wand->pose.forward(), {0, 0, -1});
  expectNear(glm::cross(wand->pose.right(), wand->pose.forward()), wand->pose.up());
  EXPECT_TRUE(wand->pressed(0));
  EXPECT_EQ(wand->joystick, glm::vec2(0.5f, -0.25f));
}

TEST(TrackerCalibration, RefusesAxesThatAreNotPerpendicular) {
  TrackingSpec spec;
  spec.headUp = {1, 0, 0.1f};
  EXPECT_THROW(TrackerCalibration{spec}, Error);
}

TEST(TrackerCalibration, AnUntrackedWandKeepsButtonsAndAMissingHeadIsNone) {
  TrackerFrame f = frameWith({0, 0, 0}, glm::mat3(1.0f));
  f.flysticks[0].quality = -1.0f;
  f.bodies.clear();
  const TrackerCalibration c{TrackingSpec{}};
  EXPECT_FALSE(c.head(f));
  const auto wand = c.wand(f);
  ASSERT_TRUE(wand);
  EXPECT_FALSE(wand->tracked);
  EXPECT_TRUE(wand->pressed(0));
}

TrackerMeasurement measured(std::uint64_t sequence, double at, glm::vec3 headMm) {
  TrackerFrame f = frameWith(headMm, glm::mat3(1.0f));
  f.frame = std::uint32_t(1000 + sequence);
  return TrackerMeasurement{f, sequence, at};
}

TEST(TrackingSampler, InactiveUntilTheFirstMeasurement) {
  TrackingSampler s{TrackingSpec{}};
  const TrackingSample none = s.sample(nullptr, 5.0);
  EXPECT_FALSE(none.active);
  EXPECT_FALSE(none.stale);
  EXPECT_FALSE(none.headTracked);
}

TEST(TrackingSampler, HoldsTheLastPoseWhenMeasurementsStop) {
  TrackingSpec spec;
  spec.staleMs = 250.0f;
  TrackingSampler s(spec);
  const TrackerMeasurement first = measured(1, 10.0, {100, 200, 1700});
  TrackingSample a = s.sample(&first, 10.0);
  EXPECT_TRUE(a.active && a.headTracked && !a.stale);
  EXPECT_EQ(a.trackerFrame, 1001u);
  expectNear(a.head.position, {0.1f, 0.2f, 1.7f});
  // The same measurement again: still fresh within 250 ms, stale after.
  EXPECT_FALSE(s.sample(&first, 10.24).stale);
  const TrackingSample late = s.sample(&first, 10.26);
  EXPECT_TRUE(late.stale);
  EXPECT_TRUE(s.lost());
  EXPECT_EQ(late.head, a.head);  // held, not dropped
  EXPECT_FALSE(late.wand.tracked);
  // A new measurement: fresh again, at its pose.
  const TrackerMeasurement second = measured(2, 10.3, {0, 0, 1600});
  const TrackingSample b = s.sample(&second, 10.3);
  EXPECT_FALSE(b.stale);
  EXPECT_FALSE(s.lost());
  expectNear(b.head.position, {0, 0, 1.6f});
  EXPECT_EQ(b.trackerFrame, 1002u);
}

TEST(TrackingSampler, AHeadMissingFromFreshMeasurementsGoesStaleToo) {
  TrackingSampler s{TrackingSpec{}};
  const TrackerMeasurement first = measured(1, 0.0, {0, 0, 1700});
  s.sample(&first, 0.0);
  TrackerMeasurement without = measured(2, 0.5, {0, 0, 0});
  without.frame.bodies.clear();  // the glasses left the tracked volume; the wand did not
  const TrackingSample t = s.sample(&without, 0.5);
  EXPECT_TRUE(t.stale);
  expectNear(t.head.position, {0, 0, 1.7f});
  EXPECT_TRUE(t.wand.tracked);
}

// DTrack lists every Flystick in every datagram, tracked or not (quality -1
// when occluded), with its buttons and joystick either way.
TEST(TrackingSampler, AnOccludedWandIsUntrackedAtOnceWithItsButtonsAndJoystickLive) {
  TrackingSpec spec;
  spec.staleMs = 500.0f;
  TrackingSampler s(spec);
  const TrackerMeasurement seen = measured(1, 0.0, {0, 0, 1700});
  const TrackingSample a = s.sample(&seen, 0.0);
  ASSERT_TRUE(a.wand.tracked);
  for (std::uint64_t n = 2; n <= 6; ++n) {  // well within stale_ms of the tracked one, and after
    TrackerMeasurement hidden = measured(n, 0.01 * double(n), {0, 0, 1700});
    TrackedFlystick& f = hidden.frame.flysticks[0];
    f.quality = -1.0f;
    f.position = glm::vec3(0.0f);  // DTrack sends zeros for an untracked pose
    f.rotation = glm::mat3(0.0f);
    f.buttons = std::uint32_t(n);
    f.controllers = {0.0f, 0.75f};
    const TrackingSample t = s.sample(&hidden, 0.01 * double(n));
    SCOPED_TRACE(n);
    EXPECT_FALSE(t.wand.tracked);  // the first untracked datagram as every later one
    EXPECT_TRUE(t.wand.present);
    EXPECT_EQ(t.wand.buttons, std::uint32_t(n));
    EXPECT_EQ(t.wand.joystick, glm::vec2(0.0f, 0.75f));
  }
  // Tracked again: its new pose at once.
  TrackerMeasurement back = measured(7, 0.1, {0, 0, 1700});
  back.frame.flysticks[0].position = {300.0f, 0.0f, 1000.0f};
  const TrackingSample b = s.sample(&back, 0.1);
  EXPECT_TRUE(b.wand.tracked);
  expectNear(b.wand.pose.position, {0.3f, 0.0f, 1.0f});
  // The radio quiet past stale_ms: buttons and joystick released.
  const TrackingSample quiet = s.sample(&back, 0.7);
  EXPECT_FALSE(quiet.wand.present);
  EXPECT_EQ(quiet.wand.buttons, 0u);
  EXPECT_EQ(quiet.wand.joystick, glm::vec2(0.0f));
}

TEST(TrackingSampler, TheNewestMeasurementIsTheOneUsed) {
  // Whatever the receiver holds when a frame starts is that frame's sample.
  TrackingSampler s{TrackingSpec{}};
  for (std::uint64_t n = 1; n <= 5; ++n) {
    const TrackerMeasurement m = measured(n, double(n), {float(n), 0, 1700});
    const TrackingSample t = s.sample(&m, double(n));
    EXPECT_EQ(t.trackerFrame, 1000 + n);
    expectNear(t.head.position, {0.001f * float(n), 0, 1.7f});
  }
}

}  // namespace
}  // namespace sandstorm
