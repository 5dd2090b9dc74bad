#include "core/util/nearest_name.h"

#include <algorithm>
#include <cctype>

namespace sandstorm {

std::size_t editDistance(std::string_view a, std::string_view b) {
  const auto same = [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) ==
           std::tolower(static_cast<unsigned char>(y));
  };
  // d[i][j]: the distance between a's first i letters and b's first j.
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i)
    d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j)
    d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = same(a[i - 1], b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::optional<std::string> nearestName(std::string_view typed,
                                       const std::vector<std::string>& names) {
  // Names are short; a long word (a fuzzed file's key) is no typo of one, and
  // its distances would cost time and memory for nothing.
  constexpr std::size_t kLongest = 64;
  if (typed.size() > kLongest) return std::nullopt;
  const std::size_t limit = std::max<std::size_t>(1, typed.size() / 3);
  std::optional<std::string> best;
  std::size_t bestDistance = limit + 1;
  bool tie = false;
  for (const std::string& name : names) {
    if (name.size() > kLongest) continue;
    const std::size_t distance = editDistance(typed, name);
    if (distance < bestDistance) {
      best = name;
      bestDistance = distance;
      tie = false;
    } else if (distance == bestDistance && best && *best != name) {
      tie = true;
    }
  }
  if (!best || tie || *best == typed) return std::nullopt;
  return best;
}

std::string didYouMean(std::string_view typed, const std::vector<std::string>& names) {
  const std::optional<std::string> name = nearestName(typed, names);
  return name ? " (did you mean '" + *name + "'?)" : std::string();
}

}  // namespace sandstorm
