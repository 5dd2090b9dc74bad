// FasterChoice against hand-made times: it tries the ways in blocks, keeps
// the one with the lower median block, tries again after its keep, waits for
// late times and drops those of an ended trial.
#include "core/util/faster_choice.h"

#include <gtest/gtest.h>

namespace sandstorm {
namespace {

// `runs` runs, each timed (where asked) at once with cost(way, run).
template <typename Cost>
std::vector<int> run(FasterChoice& c, int runs, Cost cost) {
  std::vector<int> ways;
  for (int i = 0; i < runs; ++i) {
    const FasterChoice::Run r = c.next();
    ways.push_back(r.way);
    if (r.ticket >= 0) c.measured(r.ticket, cost(r.way, i));
  }
  return ways;
}

TEST(FasterChoice, TriesBothInBlocksThenKeepsTheOneWithTheLowerMedian) {
  FasterChoice c(3, 1, 4);
  // Way 1 is faster but for one slow outlier, which the median ignores.
  const auto cost = [](int way, int i) { return way == 0 ? 2.0 : (i == 1 ? 50.0 : 1.0); };
  EXPECT_EQ(run(c, 10, cost), (std::vector<int>{0, 1, 0, 1, 0, 1, 1, 1, 1, 1}));
  EXPECT_EQ(c.kept(), 1);
  // After its keep it tries both again, and follows a change of costs.
  EXPECT_EQ(run(c, 6, [](int way, int) { return way == 0 ? 1.0 : 3.0; }),
            (std::vector<int>{0, 1, 0, 1, 0, 1}));
  EXPECT_EQ(c.kept(), 0);
  EXPECT_EQ(c.next().way, 0);
}

// One chooser serving two views a frame, a cheap one and a dear one: blocks
// of two runs give each way both views, so the comparison is fair. Runs
// alternating one by one would give way 0 only the cheap view and choose it
// though it is slower.
TEST(FasterChoice, BlocksCoverEveryViewOfAFrame) {
  const auto cost = [](int way, int i) {
    const double view = i % 2 == 0 ? 1.0 : 10.0;  // the frame's first and second views
    return view * (way == 0 ? 1.5 : 1.0);         // way 1 is faster in both
  };
  FasterChoice blocks(3, 2, 100);
  EXPECT_EQ(run(blocks, 12, cost), (std::vector<int>{0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1}));
  EXPECT_EQ(blocks.kept(), 1);
  FasterChoice single(3, 1, 100);
  run(single, 6, cost);
  EXPECT_EQ(single.kept(), 0) << "the bias blocks avoid";
}

// After a start the work changes (trails grow), so early choices are kept
// briefly: as long as a trial took, then twice as long each time, up to keep.
TEST(FasterChoice, KeepsEachChoiceTwiceAsLongAsTheLastUpToKeep) {
  FasterChoice c(1, 1, 7);
  std::vector<int> kept;  // the length of each stretch of untimed runs
  int untimed = 0;
  for (int i = 0; i < 40; ++i) {
    const FasterChoice::Run r = c.next();
    if (r.ticket < 0) {
      ++untimed;
      continue;
    }
    if (untimed > 0) kept.push_back(untimed);
    untimed = 0;
    c.measured(r.ticket, r.way == 0 ? 1.0 : 2.0);
  }
  EXPECT_EQ(kept, (std::vector<int>{2, 4, 7, 7, 7}));
}

TEST(FasterChoice, WaitsForLateTimesAndDropsThoseOfAnEndedTrial) {
  FasterChoice c(1, 2, 3);
  std::vector<FasterChoice::Run> runs;
  for (int i = 0; i < 4; ++i)
    runs.push_back(c.next());
  EXPECT_EQ(runs[0].way, 0);
  EXPECT_EQ(runs[2].way, 1);
  // Times arrive late and out of order; a block counts only when complete.
  c.measured(runs[2].ticket, 1.0);
  c.measured(runs[0].ticket, 3.0);
  c.measured(runs[3].ticket, 1.0);
  EXPECT_EQ(c.kept(), -1) << "way 0's block still misses a run";
  c.measured(runs[1].ticket, 3.0);
  EXPECT_EQ(c.kept(), 1);
  // Kept for 3 runs, untimed; then a new trial, where the old tickets count for nothing.
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(c.next().ticket, -1);
  const FasterChoice::Run a = c.next(), b = c.next();
  EXPECT_EQ(a.way, 0);
  for (const FasterChoice::Run& old : runs)
    c.measured(old.ticket, 0.001);
  EXPECT_EQ(c.kept(), -1);
  c.measured(a.ticket, 0.5);
  c.measured(b.ticket, 0.5);
  const FasterChoice::Run d = c.next(), e = c.next();
  c.measured(d.ticket, 4.0);
  c.measured(e.ticket, 4.0);
  EXPECT_EQ(c.kept(), 0);
}

}  // namespace
}  // namespace sandstorm
