// FramePacer (run.max_fps): a loop paced to N frames a second takes at least
// the time those frames stand for; a slow frame is not made up; no limit,
// no period.
#include "core/util/frame_pacer.h"

#include <gtest/gtest.h>

namespace sandstorm {
namespace {

using Clock = std::chrono::steady_clock;

TEST(FramePacer, TwentyFramesAtTwoHundredASecondTakeAtLeastATenthOfASecond) {
  FramePacer pacer(200.0);
  const Clock::time_point start = Clock::now();
  for (int i = 0; i < 20; ++i)
    pacer.wait();
  EXPECT_GE(Clock::now() - start, std::chrono::milliseconds(99));
}

TEST(FramePacer, ASlowFrameIsNotMadeUpByHurrying) {
  FramePacer pacer(100.0);  // 10 ms a frame
  pacer.wait();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // a frame five periods long
  const Clock::time_point before = Clock::now();
  pacer.wait();
  // A full period from now, not the four it fell behind spent at once.
  EXPECT_GE(Clock::now() - before, std::chrono::milliseconds(9));
}

TEST(FramePacer, NoLimitHasNoPeriod) {
  EXPECT_EQ(FramePacer(0.0).period(), Clock::duration::zero());
  EXPECT_EQ(FramePacer(-5.0).period(), Clock::duration::zero());
  EXPECT_EQ(FramePacer(50.0).period(), std::chrono::milliseconds(20));
}

}  // namespace
}  // namespace sandstorm
