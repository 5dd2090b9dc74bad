// sandstorm-tracker-sim's scripted user: keyframes interpolate, the frames it
// makes travel as DTrack datagrams and come back as the poses the script
// describes (in the room, through the default calibration), and bad path
// files name their line and key.
#include "core/tracking/tracker_script.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/tracking/dtrack_parser.h"
#include "core/tracking/dtrack_writer.h"
#include "core/tracking/tracker_calibration.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

const char* kPath = R"(loop = false
head_body = 2
wand_flystick = 1
[[key]]
time = 0.0
head = [0.0, 0.0, 1.7]
wand = [0.2, 0.4, 1.2]
wand_pitch_deg = 30.0
buttons = 1
[[key]]
time = 2.0
head = [1.0, -1.0, 1.5]
head_yaw_deg = 180.0
buttons = 2
joystick = [0.5, -1.0]
)";

TEST(TrackerScript, KeyframesInterpolateAndButtonsHold) {
  const TrackerScript s = TrackerScript::parse(kPath, "path.toml");
  EXPECT_FALSE(s.loop);
  EXPECT_EQ(s.duration(), 2.0);
  const TrackerFrame mid = s.at(1.0, 77);
  EXPECT_EQ(*mid.frame, 77u);
  const TrackedBody* head = mid.body(2);
  ASSERT_TRUE(head);
  EXPECT_NEAR(head->position.x, 500.0f, 1e-3f);
  EXPECT_NEAR(head->position.z, 1600.0f, 1e-3f);
  const TrackedFlystick* wand = mid.flystick(1);
  ASSERT_TRUE(wand);
  EXPECT_EQ(wand->buttons, 1u);  // holds until the next keyframe
  EXPECT_EQ(s.at(2.0, 0).flystick(1)->buttons, 2u);
  EXPECT_EQ(s.at(5.0, 0).body(2)->position, glm::vec3(1000.0f, -1000.0f, 1500.0f));  // held
}

TEST(TrackerScript, FramesComeBackAsTheScriptsPosesInTheRoom) {
  const TrackerScript s = TrackerScript::parse(kPath, "path.toml");
  TrackingSpec spec;
  spec.headBody = 2;
  spec.wandFlystick = 1;
  const TrackerCalibration room(spec);
  const TrackerFrame f = parseDTrack(writeDTrack(s.at(2.0, 5)));
  const auto head = room.head(f);
  ASSERT_TRUE(head);
  EXPECT_NEAR(head->position.x, 1.0f, 1e-6f);
  EXPECT_NEAR(head->position.y, -1.0f, 1e-6f);
  EXPECT_NEAR(head->position.z, 1.5f, 1e-6f);
  // Yaw 180: facing -x, so the right eye is towards +y.
  EXPECT_NEAR(head->forward().x, -1.0f, 1e-6f);
  EXPECT_NEAR(head->right().y, 1.0f, 1e-6f);
  const auto wand = room.wand(f);
  ASSERT_TRUE(wand);
  // Pitch 30 held from the first keyframe (unset items hold): pointing +y, 30 degrees up.
  EXPECT_NEAR(wand->pose.forward().y, std::cos(glm::radians(30.0f)), 1e-6f);
  EXPECT_NEAR(wand->pose.forward().z, std::sin(glm::radians(30.0f)), 1e-6f);
  EXPECT_EQ(wand->joystick, glm::vec2(0.5f, -1.0f));
}

TEST(TrackerScript, TheBuiltInWalkStaysInTheCaveAndLoops) {
  const TrackerScript s = TrackerScript::builtIn();
  for (double t = 0.0; t < 2.0 * s.duration(); t += 0.25) {
    const TrackerFrame f = s.at(t, 0);
    ASSERT_EQ(f.bodies.size(), 1u);
    const glm::vec3 p = f.bodies[0].position / 1000.0f;
    EXPECT_LT(std::abs(p.x), 1.5f);
    EXPECT_LT(std::abs(p.y), 1.5f);
    EXPECT_GT(p.z, 1.5f);
    // Unassigned buttons only: the built-in walk clicks nothing in Sandstorm.
    EXPECT_EQ(f.flysticks[0].buttons & 3u, 0u);
  }
  EXPECT_EQ(s.at(1.0, 0).bodies[0].position, s.at(1.0 + s.duration(), 0).bodies[0].position);
}

TEST(TrackerScript, BadPathFilesNameTheirLineAndKey) {
  const auto errorOf = [](const std::string& text) {
    try {
      TrackerScript::parse(text, "p.toml");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(errorOf("loop = 1\n[[key]]\ntime = 0\n").find("p.toml:1: loop"), std::string::npos);
  EXPECT_NE(errorOf("[[key]]\ntime = 1\n[[key]]\ntime = 0.5\n").find("increase"),
            std::string::npos);
  EXPECT_NE(errorOf("[[key]]\nhead = [0, 0]\ntime = 0\n").find("key.head"), std::string::npos);
  EXPECT_NE(errorOf("[[key]]\ntime = 0\njoystick = [2, 0]\n").find("-1..1"), std::string::npos);
  EXPECT_NE(errorOf("[[key]]\ntime = 0\nhed = [0, 0, 1]\n").find("unknown key"), std::string::npos);
  EXPECT_NE(errorOf("[[key]]\nhead = [0, 0, 1]\n").find("needs a time"), std::string::npos);
  EXPECT_NE(errorOf("loop = true\n").find("at least one [[key]]"), std::string::npos);
  EXPECT_NE(errorOf("[[key]]\ntime = nan\n").find("finite"), std::string::npos);
  EXPECT_NE(errorOf("loop = " + std::string(5000, '[') + "\n").find("p.toml:1: arrays"),
            std::string::npos);
}

}  // namespace
}  // namespace sandstorm
