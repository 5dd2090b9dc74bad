#include "core/sim/session_log.h"

#include <gtest/gtest.h>

#include <set>

#include "core/util/error.h"

namespace sandstorm {
namespace {

TEST(SessionLog, FormatsAndParsesEveryKindOfChange) {
  Emitter e;
  e.shape = EmitterShape::Disc;
  e.position = {1, -2, 0.5f};
  e.rate = 2500;
  const std::vector<StateChange> changes = {StateChange::set("emitter.0.rate", 50000.0f),
                                            StateChange::set("sim.gravity", glm::vec3(0, 0, -3)),
                                            StateChange::set("render.mode", std::string("points")),
                                            StateChange::addEmitter(e),
                                            StateChange::removeEmitter(1),
                                            StateChange::reset()};
  std::string text;
  for (std::size_t i = 0; i < changes.size(); ++i)
    text += std::to_string(10 * i) + " " + formatChange(changes[i]) + "\n";
  const std::vector<ScheduledChange> parsed = parseSessionLog(text, "log");
  ASSERT_EQ(parsed.size(), changes.size());
  for (std::size_t i = 0; i < changes.size(); ++i) {
    EXPECT_EQ(parsed[i].frame, 10u * i);
    EXPECT_EQ(describe(parsed[i].change), describe(changes[i]));
  }
  EXPECT_EQ(parsed[3].change.emitter.shape, EmitterShape::Disc);
  EXPECT_EQ(parsed[3].change.emitter.position, e.position);
  EXPECT_EQ(parsed[3].change.emitter.rate, 2500.0f);
}

// A value set by a slider or worked out from a field (sandstorm FILE's
// seeding plane) is any float: it replays as that float, not as six digits of it.
TEST(SessionLog, SetValuesReadBackBitForBit) {
  const float lifetime = 18.5138378f, tiny = 2.38418579e-07f, third = 1.0f / 3.0f;
  const glm::vec3 position(tiny, -third, 1234.56789f);
  const std::vector<StateChange> changes = {StateChange::set("emitter.0.lifetime", lifetime),
                                            StateChange::set("emitter.0.position", position),
                                            StateChange::set("render.size", third)};
  std::string text;
  for (const StateChange& c : changes)
    text += "0 " + formatChange(c) + "\n";
  const std::vector<ScheduledChange> parsed = parseSessionLog(text, "log");
  ASSERT_EQ(parsed.size(), 3u);
  EXPECT_EQ(std::get<float>(parsed[0].change.value), lifetime) << text;
  EXPECT_EQ(std::get<glm::vec3>(parsed[1].change.value), position) << text;
  EXPECT_EQ(std::get<float>(parsed[2].change.value), third) << text;
}

TEST(SessionLog, BadLinesNameTheirLine) {
  const auto errorOf = [](const std::string& text) {
    try {
      parseSessionLog(text, "s.log");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(
      errorOf("# c\n5 set render.size 0.1\nx set a b\n").find("s.log:3: expected a frame number"),
      std::string::npos);
  EXPECT_NE(errorOf("5 set render.sise 1\n").find("s.log:1: unknown attribute 'render.sise'"),
            std::string::npos);
  EXPECT_NE(errorOf("5 jump\n").find("s.log:1: unknown change 'jump'"), std::string::npos);
  EXPECT_NE(errorOf("9 reset\n5 reset\n").find("s.log:2: frame 5 comes after frame 9"),
            std::string::npos);
  EXPECT_NE(errorOf("5 set sim.maximum lots\n").find("s.log:1"), std::string::npos);
  EXPECT_NE(errorOf("5 field-wait 3\n").find("s.log:1: expected 'field-wait' alone"),
            std::string::npos);
  const SessionLog waits = parseSession("4 field-wait\n5 field-wait\n", "s.log");
  EXPECT_EQ(waits.fieldWaits, (std::set<std::uint32_t>{4, 5}));
}

TEST(SessionLog, TrackingAndNavigationReadBackBitForBit) {
  TrackingSample s;
  s.active = true;
  s.stale = true;
  s.trackerFrame = 4000000000u;
  s.headTracked = true;
  s.head = {{0.1f + 1e-7f, -1.0f / 3.0f, 1.7f}, glm::mat3(0.6f, 0.8f, 0, -0.8f, 0.6f, 0, 0, 0, 1)};
  s.wand = {.present = true,
            .tracked = true,
            .pose = {{1e-30f, -2.5f, 3.25f}, glm::mat3(1.0f)},
            .buttons = 0x21,
            .joystick = {-0.123456789f, 1.0f}};
  TrackingSample noHead;
  noHead.active = true;
  noHead.trackerFrame = 7;
  const Navigation n{{-1.0f, 2.6f, 1e-8f}, 0.1f, 0.35f};
  const std::string text = "3 " + formatTracking(s) + "\n4 " + formatTracking(noHead) + "\n5 " +
                           formatNavigation(n) + "\n6 set render.size 0.2\n";
  const SessionLog log = parseSession(text, "log");
  ASSERT_EQ(log.tracking.size(), 2u);
  EXPECT_EQ(log.tracking[0].frame, 3u);
  EXPECT_EQ(log.tracking[0].sample, s);  // every float exactly
  EXPECT_EQ(log.tracking[1].sample, noHead);
  ASSERT_EQ(log.navigation.size(), 1u);
  EXPECT_EQ(log.navigation[0].frame, 5u);
  EXPECT_EQ(log.navigation[0].navigation.offset, n.offset);
  EXPECT_EQ(log.navigation[0].navigation.yawRadians, n.yawRadians);
  EXPECT_EQ(log.navigation[0].navigation.scale, n.scale);
  EXPECT_EQ(log.changes.size(), 1u);
}

TEST(SessionLog, FieldSwitchesReadBack) {
  const SessionLog log =
      parseSession("10 field data/tornado.vti\n20 field analytic:tornado\n", "log");
  ASSERT_EQ(log.fields.size(), 2u);
  EXPECT_EQ(log.fields[0].frame, 10u);
  EXPECT_EQ(log.fields[0].source, "data/tornado.vti");
  EXPECT_EQ(log.fields[1].source, "analytic:tornado");
  try {
    parseSession("5 field a b\n", "s.log");
    FAIL() << "two sources accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("s.log:1: expected 'field SOURCE'"), std::string::npos)
        << e.what();
  }
}

TEST(SessionLog, BadTrackingLinesNameTheirLine) {
  const auto errorOf = [](const std::string& text) {
    try {
      parseSession(text, "s.log");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(errorOf("1 track frame=1 stale=0 head=1,2,3 wand=-\n").find("s.log:1: track head"),
            std::string::npos);
  EXPECT_NE(errorOf("1 track frame=1 stale=2 head=- wand=-\n").find("0 or 1"), std::string::npos);
  EXPECT_NE(errorOf("1 track frame=1 head=- wand=-\n").find("expected frame=, stale="),
            std::string::npos);
  EXPECT_NE(errorOf("1 track frame=1 stale=0 head=- wand=- x=1\n").find("unknown item"),
            std::string::npos);
  EXPECT_NE(
      errorOf("1 track frame=1 stale=0 head=nan,0,0,1,0,0,0,1,0,0,0,1 wand=-\n").find("track head"),
      std::string::npos);
  EXPECT_NE(errorOf("1 navigate 1,2,3,0,0\n").find("positive scale"), std::string::npos);
  EXPECT_NE(errorOf("1 navigate 1,2,3\n").find("expected 5"), std::string::npos);
}

}  // namespace
}  // namespace sandstorm
