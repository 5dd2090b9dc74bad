// ProgressBoard: what a loading window shows is the newest live meter's
// progress, as the log says it, and nothing once the work is over.
#include "core/util/progress_board.h"

#include <gtest/gtest.h>

#include <thread>

#include "core/util/progress_meter.h"

namespace sandstorm {
namespace {

TEST(ProgressBoard, ShowsTheNewestLiveMeterAndNothingOnceItEnds) {
  ProgressBoard& board = ProgressBoard::instance();
  EXPECT_FALSE(board.snapshot().has_value());
  {
    ProgressMeter reading("reading wind.vti", 2'000'000'000, "bytes");
    reading.add(500'000'000);
    std::optional<ProgressSnapshot> s = board.snapshot();
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->what, "reading wind.vti");
    EXPECT_EQ(s->done, 500'000'000u);
    EXPECT_EQ(s->total, 2'000'000'000u);
    EXPECT_DOUBLE_EQ(s->fraction(), 0.25);
    {
      ProgressMeter resampling("resampling wind.vtu", 0, "cells");  // open-ended
      resampling.add(1200);
      s = board.snapshot();
      ASSERT_TRUE(s.has_value());
      EXPECT_EQ(s->what, "resampling wind.vtu");
      EXPECT_EQ(s->fraction(), 0.0);
      EXPECT_EQ(s->secondsLeft, 0.0);
      EXPECT_EQ(s->text().rfind("resampling wind.vtu: 1200 cells, ", 0), 0u) << s->text();
    }
    s = board.snapshot();  // back to the one still under way
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->what, "reading wind.vti");
  }
  EXPECT_FALSE(board.snapshot().has_value());
}

TEST(ProgressBoard, TheRateAndTimeLeftFollowWhatIsDone) {
  ProgressMeter meter("reading wind.vti", 4'000'000, "bytes");
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  meter.add(1'000'000);
  const ProgressSnapshot s = *ProgressBoard::instance().snapshot();
  EXPECT_GT(s.seconds, 0.04);
  EXPECT_NEAR(s.rate, 1'000'000 / s.seconds, 1e-6 * s.rate);
  // Three quarters left at that rate: three times the time taken so far.
  EXPECT_NEAR(s.secondsLeft, 3.0 * s.seconds, 1e-9 + 1e-6 * s.secondsLeft);
  const std::string text = s.text();
  EXPECT_EQ(text.rfind("reading wind.vti: 25% (1.0 MB of 4.0 MB), ", 0), 0u) << text;
  EXPECT_NE(text.find(" s left"), std::string::npos) << text;
}

}  // namespace
}  // namespace sandstorm
