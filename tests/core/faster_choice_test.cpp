// FasterChoice against hand-made times: it tries both ways in turn, keeps the
// one with the lower median, tries again after its keep, and drops late times.
#include "core/util/faster_choice.h"

#include <gtest/gtest.h>

namespace sandstorm {
namespace {

// Runs `runs` rounds with each way's time given by `cost`, measured at once.
template <typename Cost>
std::vector<int> run(FasterChoice& c, int runs, Cost cost) {
  std::vector<int> ways;
  for (int i = 0; i < runs; ++i) {
    const int way = c.next();
    ways.push_back(way);
    if (c.timing()) c.measured(way, cost(way, i), c.trial());
  }
  return ways;
}

TEST(FasterChoice, TriesBothInTurnThenKeepsTheOneWithTheLowerMedian) {
  FasterChoice c(3, 4);
  // Way 1 is faster but for one slow outlier, which the median ignores.
  const auto cost = [](int way, int i) { return way == 0 ? 2.0 : (i == 1 ? 50.0 : 1.0); };
  const std::vector<int> ways = run(c, 6 + 4, cost);
  EXPECT_EQ(ways, (std::vector<int>{0, 1, 0, 1, 0, 1, 1, 1, 1, 1}));
  EXPECT_EQ(c.kept(), 1);
  // After its keep it tries both again, and follows a change of costs.
  const std::vector<int> again = run(c, 6, [](int way, int) { return way == 0 ? 1.0 : 3.0; });
  EXPECT_EQ(again, (std::vector<int>{0, 1, 0, 1, 0, 1}));
  EXPECT_EQ(c.kept(), 0);
  EXPECT_EQ(c.next(), 0);
}

TEST(FasterChoice, WaitsForTimesThatArriveLateAndDropsThoseOfAnEndedTrial) {
  FasterChoice c(2, 3);
  // Times come back two runs late (GPU queries).
  struct Pending {
    int way, trial;
  };
  std::vector<Pending> pending;
  std::vector<int> ways;
  for (int i = 0; i < 6; ++i) {
    const int way = c.next();
    ways.push_back(way);
    if (c.timing()) pending.push_back({way, c.trial()});
    if (pending.size() > 2) {
      c.measured(pending.front().way, pending.front().way == 0 ? 5.0 : 1.0, pending.front().trial);
      pending.erase(pending.begin());
    }
  }
  // The fourth run's time (way 1) completed the trial at run 6.
  EXPECT_EQ(ways, (std::vector<int>{0, 1, 0, 1, 0, 1}));
  EXPECT_EQ(c.kept(), 1);
  // A time still in flight from the ended trial changes nothing...
  c.measured(0, 0.001, pending.front().trial);
  EXPECT_EQ(c.kept(), 1);
  // ...nor does one from an older trial once the next has begun.
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(c.next(), 1);
  EXPECT_EQ(c.next(), 0);  // trying again
  EXPECT_TRUE(c.timing());
  c.measured(1, 0.001, c.trial() - 1);
  c.measured(1, 0.001, c.trial() - 1);
  c.measured(0, 9.0, c.trial());
  c.measured(0, 9.0, c.trial());
  EXPECT_EQ(c.kept(), -1) << "way 1 has no time of this trial yet";
  c.measured(1, 10.0, c.trial());
  c.measured(1, 10.0, c.trial());
  EXPECT_EQ(c.kept(), 0);
}

}  // namespace
}  // namespace sandstorm
