// PlaybackMeter (app/playback_meter.h): the steps a series played over the
// measured frames, a second of wall time, counted the short way round the
// series, so jumps, loops and backwards playback count what was passed.
#include <gtest/gtest.h>

#include "app/playback_meter.h"

namespace sandstorm {
namespace {

using namespace std::chrono_literals;

FieldPlaybackStatus at(std::size_t first, std::uint64_t waited = 0) {
  FieldPlaybackStatus s;
  s.steps = 100;
  s.first = first;
  s.second = (first + 1) % 100;
  s.streamed = true;
  s.framesWaited = waited;
  return s;
}

TEST(PlaybackMeter, CountsTheStepsPassedInTheMeasuredFramesOverTheirWallTime) {
  PlaybackMeter m(3);
  const PlaybackMeter::Clock::time_point t0{};
  // Warm-up frames: not measured, whatever they play or wait.
  m.frame(0, at(0, 4), t0);
  m.frame(1, at(7, 4), t0 + 1s);
  m.frame(2, at(97, 5), t0 + 2s);
  EXPECT_FALSE(m.stats());
  m.frame(3, at(97, 5), t0 + 10s);      // the first measured frame
  m.frame(4, at(98, 5), t0 + 10500ms);  // 1
  m.frame(5, at(1, 6), t0 + 11s);       // 3 more, round the loop
  m.frame(6, at(1, 7), t0 + 11500ms);   // waited
  m.frame(7, at(99, 7), t0 + 12s);      // 2 back, round the loop
  const auto s = m.stats();
  ASSERT_TRUE(s);
  EXPECT_EQ(s->frames, 5u);
  EXPECT_EQ(s->stepsPlayed, 6u);
  EXPECT_EQ(s->framesWaited, 2u);
  EXPECT_DOUBLE_EQ(s->seconds, 2.0);
  EXPECT_DOUBLE_EQ(s->stepsPerSecond(), 3.0);
}

TEST(PlaybackMeter, SaysNothingWithoutTwoMeasuredFrames) {
  PlaybackMeter m(2);
  m.frame(0, at(0), {});
  m.frame(1, at(1), {});
  m.frame(2, at(2), {});
  EXPECT_FALSE(m.stats());
}

}  // namespace
}  // namespace sandstorm
