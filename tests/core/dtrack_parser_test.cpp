// The DTrack ASCII parser against the examples of ART's DTrack2 "Technical
// Appendix" (B.2) and every kind of bad datagram a receiver meets: a
// datagram is read whole or refused with a message naming the line and item.
#include "core/tracking/dtrack_parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/tracking/dtrack_writer.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// The manual's 6d and 6df examples, with a 6df2 and a 3d line in the same style.
const std::string kManual =
    "fr 21753\r\n"
    "ts 39596.024831\r\n"
    "6dcal 2\r\n"
    "6d 1 [0 1.000][326.848 -187.216 109.503 -160.4704 -3.6963 -7.0913]"
    "[-0.940508 -0.339238 -0.019025 0.333599 -0.932599 0.137735 -0.064467 0.123194 "
    "0.990286]\r\n"
    "6df2 1 1 [2 1.000 6 2][261.103 116.520 41.085]"
    "[-0.241543 0.968868 -0.054332 -0.482366 -0.168461 -0.859619 -0.842010 -0.181427 "
    "0.508039][5 0.250 -1.000]\r\n"
    "3d 2 [74 1.000][-1.6 -43.8 1530.2][75 1.000][-73.2 -42.2 1523.2]\r\n";

std::string errorOf(std::string_view datagram) {
  try {
    parseDTrack(datagram);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(DTrackParser, ReadsTheManualsExample) {
  const TrackerFrame f = parseDTrack(kManual);
  ASSERT_TRUE(f.frame);
  EXPECT_EQ(*f.frame, 21753u);
  ASSERT_TRUE(f.timestamp);
  EXPECT_DOUBLE_EQ(*f.timestamp, 39596.024831);
  ASSERT_EQ(f.bodies.size(), 1u);
  const TrackedBody& b = f.bodies[0];
  EXPECT_EQ(b.id, 0);
  EXPECT_FLOAT_EQ(b.quality, 1.0f);
  EXPECT_EQ(b.position, glm::vec3(326.848f, -187.216f, 109.503f));  // the angles are ignored
  // b0 b1 b2 is the first column: R = [b0 b3 b6; b1 b4 b7; b2 b5 b8].
  EXPECT_FLOAT_EQ(b.rotation[0][0], -0.940508f);
  EXPECT_FLOAT_EQ(b.rotation[0][1], -0.339238f);
  EXPECT_FLOAT_EQ(b.rotation[1][0], 0.333599f);
  EXPECT_FLOAT_EQ(b.rotation[2][2], 0.990286f);
  ASSERT_EQ(f.flysticks.size(), 1u);
  const TrackedFlystick& s = f.flysticks[0];
  EXPECT_EQ(s.id, 2);
  EXPECT_TRUE(s.tracked());
  EXPECT_EQ(s.position, glm::vec3(261.103f, 116.520f, 41.085f));
  EXPECT_EQ(s.buttonCount, 6);
  EXPECT_EQ(s.buttons, 5u);
  EXPECT_TRUE(s.pressed(0));
  EXPECT_FALSE(s.pressed(1));
  EXPECT_TRUE(s.pressed(2));
  EXPECT_EQ(s.controllerCount, 2);
  EXPECT_FLOAT_EQ(s.controllers[0], 0.25f);
  EXPECT_FLOAT_EQ(s.controllers[1], -1.0f);
  ASSERT_EQ(f.markers.size(), 2u);
  EXPECT_EQ(f.markers[1].id, 75);
  EXPECT_EQ(f.markers[1].position, glm::vec3(-73.2f, -42.2f, 1523.2f));
  EXPECT_EQ(f.body(0), &f.bodies[0]);
  EXPECT_EQ(f.body(1), nullptr);
  EXPECT_EQ(f.flystick(2), &f.flysticks[0]);
}

TEST(DTrackParser, ReadsTheOlderFlystickFormat) {
  const TrackerFrame f = parseDTrack(
      "fr 7\n6df 1 [0 1.000 2][261.103 116.520 41.085 19.6522 -57.3530 116.5992]"
      "[-0.241543 0.968868 -0.054332 -0.482366 -0.168461 -0.859619 -0.842010 -0.181427 "
      "0.508039]\n");
  ASSERT_EQ(f.flysticks.size(), 1u);
  EXPECT_EQ(f.flysticks[0].buttons, 2u);
  EXPECT_TRUE(f.flysticks[0].pressed(1));
  EXPECT_EQ(f.flysticks[0].controllerCount, 0);
  EXPECT_EQ(f.flysticks[0].position, glm::vec3(261.103f, 116.520f, 41.085f));
}

TEST(DTrackParser, AnUntrackedFlystickKeepsItsButtons) {
  // The manual: quality -1, zero position, a zero matrix; buttons stay valid.
  const TrackerFrame f = parseDTrack(
      "fr 1\r\n6df2 2 2 [0 -1.000 6 2][0.000 0.000 0.000][0 0 0 0 0 0 0 0 0][1 0.000 0.000]"
      "[1 1.000 40 0][1 2 3][1 0 0 0 1 0 0 0 1][7 1]\r\n");
  ASSERT_EQ(f.flysticks.size(), 2u);
  EXPECT_FALSE(f.flysticks[0].tracked());
  EXPECT_TRUE(f.flysticks[0].pressed(0));
  EXPECT_EQ(f.flysticks[0].rotation, glm::mat3(1.0f));  // not a zero matrix to compute with
  EXPECT_EQ(f.flysticks[1].buttonCount, 40);            // two words of buttons
  EXPECT_EQ(f.flysticks[1].buttons, 7u);
}

TEST(DTrackParser, SkipsLineTypesItDoesNotRead) {
  const TrackerFrame f = parseDTrack(
      "fr 3\n6di 1 [0 1 2.135][326.848 -187.216 109.503][1 0 0 0 1 0 0 0 1]\n"
      "gl 1 [0 1.000 1 5][10 20 30][1 0 0 0 1 0 0 0 1]\n6dmt2 0 0\n");
  EXPECT_EQ(f.skippedLines, 3);
  EXPECT_TRUE(f.bodies.empty());
  EXPECT_EQ(*f.frame, 3u);
}

TEST(DTrackParser, AcceptsBareNewlinesTrailingNulsAndEmptyLists) {
  const std::string text = std::string("fr 9\n\n6d 0\n6df2 0 0\n3d 0\n") + std::string(3, '\0');
  const TrackerFrame f = parseDTrack(text);
  EXPECT_EQ(*f.frame, 9u);
  EXPECT_TRUE(f.bodies.empty() && f.flysticks.empty() && f.markers.empty());
}

TEST(DTrackParser, WhatTheWriterWritesReadsBackBitForBit) {
  TrackerFrame f;
  f.frame = 4000000000u;
  f.timestamp = 86399.5;
  f.bodies = {{3, 1.0f, {1234.5678f, -0.001f, 1700.25f}, glm::mat3(0, 1, 0, -1, 0, 0, 0, 0, 1)},
              {9, 0.5f, {1e5f, 2e5f, -3e5f}, glm::mat3(1.0f)}};
  TrackedFlystick s;
  s.id = 1;
  s.position = {-10.5f, 20.25f, 1200.125f};
  s.rotation = glm::mat3(0.6f, 0.8f, 0, -0.8f, 0.6f, 0, 0, 0, 1);
  s.buttonCount = 6;
  s.buttons = 0x21;
  s.controllerCount = 2;
  s.controllers = {-0.3333333f, 1.0f};
  f.flysticks = {s};
  f.markers = {{5, 1.0f, {1.0f, 2.0f, 3.0f}}};
  const TrackerFrame g = parseDTrack(writeDTrack(f));
  EXPECT_EQ(g.frame, f.frame);
  EXPECT_EQ(g.timestamp, f.timestamp);
  ASSERT_EQ(g.bodies.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(g.bodies[i].id, f.bodies[i].id);
    EXPECT_EQ(g.bodies[i].quality, f.bodies[i].quality);
    EXPECT_EQ(g.bodies[i].position, f.bodies[i].position);
    EXPECT_EQ(g.bodies[i].rotation, f.bodies[i].rotation);
  }
  ASSERT_EQ(g.flysticks.size(), 1u);
  EXPECT_EQ(g.flysticks[0].position, s.position);
  EXPECT_EQ(g.flysticks[0].rotation, s.rotation);
  EXPECT_EQ(g.flysticks[0].buttons, s.buttons);
  EXPECT_EQ(g.flysticks[0].controllers, s.controllers);
  EXPECT_EQ(g.markers[0].position, f.markers[0].position);
  // The older format carries the first eight buttons and no joystick.
  const TrackerFrame old = parseDTrack(writeDTrack(f, FlystickFormat::V1));
  EXPECT_EQ(old.flysticks[0].buttons, 0x21u);
  EXPECT_EQ(old.flysticks[0].position, s.position);
}

struct Bad {
  const char* name;
  std::string datagram;
  const char* says;  // part of the message
};

class DTrackParserRefuses : public testing::TestWithParam<Bad> {};

TEST_P(DTrackParserRefuses, WithAMessageNamingWhatWasWrong) {
  const std::string message = errorOf(GetParam().datagram);
  EXPECT_NE(message, "") << "accepted";
  EXPECT_NE(message.find(GetParam().says), std::string::npos) << message;
}

const std::string kRot = "[1 0 0 0 1 0 0 0 1]";

INSTANTIATE_TEST_SUITE_P(
    Cases, DTrackParserRefuses,
    testing::Values(
        Bad{"empty", "", "empty"}, Bad{"blank", " \r\n\n", "empty"},
        Bad{"count_above_blocks", "6d 3 [0 1.000][1 2 3]" + kRot + "[1 1.000][1 2 3]" + kRot,
            "body 3 of 3"},
        Bad{"count_below_blocks", "6d 1 [0 1.000][1 2 3]" + kRot + "[1 1.000][1 2 3]" + kRot,
            "after the last block"},
        Bad{"truncated_block", "6d 1 [0 1.000][1 2 3][1 0 0 0 1", "no closing"},
        Bad{"missing_count", "6d", "truncated"},
        Bad{"short_position", "6d 1 [0 1.000][1 2]" + kRot, "position block"},
        Bad{"short_matrix", "6d 1 [0 1.000][1 2 3][1 0 0 0 1 0 0 0]", "expected 9 numbers"},
        Bad{"nan", "6d 1 [0 1.000][nan 2 3]" + kRot, "finite"},
        Bad{"inf", "6df2 1 1 [0 1.000 6 2][1 2 3]" + kRot + "[0 inf 0]", "finite"},
        Bad{"nan_quality", "6d 1 [0 nan][1 2 3]" + kRot, "finite"},
        Bad{"absurd_id", "6d 1 [4000000000 1.000][1 2 3]" + kRot, "id"},
        Bad{"negative_id", "6d 1 [-1 1.000][1 2 3]" + kRot, "id"},
        Bad{"absurd_count", "6d 99999999 [0 1.000]", "number of bodies"},
        Bad{"absurd_buttons", "6df2 1 1 [0 1.000 99999 0][1 2 3]" + kRot + "[]", "button count"},
        Bad{"buttons_block", "6df2 1 1 [0 1.000 6 2][1 2 3]" + kRot + "[1 0.5]",
            "expected 3 numbers"},
        Bad{"controller_range", "6df2 1 1 [0 1.000 6 2][1 2 3]" + kRot + "[1 0.5 7]", "-1..1"},
        Bad{"far_away", "6d 1 [0 1.000][1e9 2 3]" + kRot, "beyond any room"},
        Bad{"not_rotation", "6d 1 [0 1.000][1 2 3][1 1 1 1 1 1 1 1 1]", "not a rotation"},
        Bad{"mirror", "6d 1 [0 1.000][1 2 3][-1 0 0 0 1 0 0 0 1]", "not a rotation"},
        Bad{"duplicate_id", "6d 2 [4 1.000][1 2 3]" + kRot + "[4 1.000][1 2 3]" + kRot, "twice"},
        Bad{"duplicate_line", "fr 1\nfr 2\n", "second line"},
        Bad{"word_for_number", "fr twelve", "integer"},
        Bad{"frame_too_big", "fr 99999999999", "frame counter"},
        Bad{"bad_timestamp", "ts -5", "timestamp"},
        Bad{"binary", std::string("fr 1\n\x01\x02\xff", 8), "not text"},
        Bad{"junk_type", "7777777777777777777777777", "not a DTrack line type"},
        Bad{"quality_range", "6d 1 [0 5][1 2 3]" + kRot, "quality"},
        Bad{"oversized", std::string(65537, 'a'), "exceed the limit"}),
    [](const testing::TestParamInfo<Bad>& info) { return std::string(info.param.name); });

// Any prefix of a good datagram either fails or holds only what the whole one
// holds: a pose is never half-read (cut numbers fail for want of a ']').
TEST(DTrackParser, EveryTruncationFailsOrHoldsOnlyWholeItems) {
  const TrackerFrame whole = parseDTrack(kManual);
  int refused = 0;
  for (std::size_t n = 0; n < kManual.size(); ++n) {
    TrackerFrame part;
    try {
      part = parseDTrack(std::string_view(kManual).substr(0, n));
    } catch (const Error&) {
      ++refused;
      continue;
    }
    for (const TrackedBody& b : part.bodies) {
      ASSERT_TRUE(whole.body(b.id)) << n;
      EXPECT_EQ(b.position, whole.body(b.id)->position) << n;
      EXPECT_EQ(b.rotation, whole.body(b.id)->rotation) << n;
    }
    for (const TrackedFlystick& s : part.flysticks) {
      EXPECT_EQ(s.position, whole.flystick(s.id)->position) << n;
      EXPECT_EQ(s.buttons, whole.flystick(s.id)->buttons) << n;
      EXPECT_EQ(s.controllers, whole.flystick(s.id)->controllers) << n;
    }
  }
  EXPECT_GT(refused, int(kManual.size()) * 3 / 4);
}

// Random bytes and random edits of a good datagram: refused with an Error, or
// read into finite positions and true rotations; never a crash or anything else.
TEST(DTrackParser, RandomJunkAndEditsAreRefusedOrReadSane) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> byte(0, 255);
  int read = 0;
  for (int i = 0; i < 4000; ++i) {
    std::string d = kManual;
    const int edits = 1 + i % 8;
    for (int e = 0; e < edits; ++e)
      d[std::size_t(random() % d.size())] = char(i % 2 ? byte(random) : " []0.-9e\n"[random() % 9]);
    TrackerFrame f;
    try {
      f = parseDTrack(d);
    } catch (const Error&) {
      continue;
    }
    ++read;
    for (const TrackedBody& b : f.bodies) {
      EXPECT_TRUE(std::isfinite(b.position.x + b.position.y + b.position.z));
      const glm::mat3 gram = glm::transpose(b.rotation) * b.rotation;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(gram[c][c], 1.0f, 0.05f) << d;
      EXPECT_GT(glm::determinant(b.rotation), 0.0f) << d;
    }
  }
  EXPECT_GT(read, 0);  // some edits land in places that leave a valid datagram
}

}  // namespace
}  // namespace sandstorm
