// raiseBudget(): the end of an over-budget error, naming the setting that
// fits and the value it needs ("; raise field.memory_budget to at least
// 1.57 GiB"): the value rounded up, never down, and written as the
// configuration reads it back (parseByteSize). An error where a coarser grid
// fits too names field.resolution as well (the extractor's, the series').
#pragma once

#include <string>

namespace sandstorm {

// `needed`: the smallest field.memory_budget the failed check would pass, in bytes.
std::string raiseBudget(double needed);

// The value alone: "1.57 GiB", at least `bytes` and at least the 1 MiB the
// configuration takes.
std::string budgetValueAtLeast(double bytes);

}  // namespace sandstorm
