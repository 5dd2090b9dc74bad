#include "core/io/ascii_numbers.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <system_error>
#include <utility>
#include <vector>

#include "core/util/parallel_for.h"

namespace sandstorm {
namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// The start and end of the next token at or after `at` before `end`; {end, end} when none.
std::pair<std::size_t, std::size_t> nextToken(std::string_view text, std::size_t at,
                                              std::size_t end) {
  while (at < end && isAsciiSpace(text[at]))
    ++at;
  std::size_t stop = at;
  while (stop < end && !isAsciiSpace(text[stop]))
    ++stop;
  return {at, stop};
}

}  // namespace

bool readAsciiNumber(std::string_view token, double& value) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if ((ec != std::errc() && ec != std::errc::result_out_of_range) ||
      end != token.data() + token.size())
    return false;
  value = v;
  return true;
}

template <class T>
AsciiScan parseAsciiNumbers(std::string_view text, std::size_t from, std::size_t n, T* out,
                            const std::function<void(std::size_t)>& passed,
                            const AsciiWindows& windows) {
  AsciiScan scan{0, from};
  while (scan.parsed < n) {
    std::size_t at = scan.end;
    while (at < text.size() && isAsciiSpace(text[at]))
      ++at;
    if (at >= text.size()) break;
    // The window, and its parts, end at whitespace: no token is cut.
    std::size_t end = std::min(text.size(), at + windows.window);
    while (end < text.size() && !isAsciiSpace(text[end]))
      ++end;
    std::vector<std::size_t> cuts{at};
    for (std::size_t c = at + windows.part; c < end; c += windows.part) {
      while (c < end && !isAsciiSpace(text[c]))
        ++c;
      if (c < end) cuts.push_back(c);
    }
    cuts.push_back(end);
    const std::size_t parts = cuts.size() - 1;

    std::vector<std::size_t> first(parts);  // the index of each part's first token
    forChunks(
        parts,
        [&](std::size_t b, std::size_t e) {
          for (std::size_t p = b; p < e; ++p) {
            std::size_t count = 0;
            for (auto t = nextToken(text, cuts[p], cuts[p + 1]); t.first < cuts[p + 1];
                 t = nextToken(text, t.second, cuts[p + 1]))
              ++count;
            first[p] = count;
          }
        },
        1);
    std::size_t index = scan.parsed;
    for (std::size_t& f : first)
      index += std::exchange(f, index);

    std::vector<std::size_t> bad(parts, kNone), badIndex(parts), reached(parts);
    forChunks(
        parts,
        [&](std::size_t b, std::size_t e) {
          for (std::size_t p = b; p < e; ++p) {
            std::size_t i = first[p], pos = cuts[p];
            for (auto t = nextToken(text, pos, cuts[p + 1]); i < n && t.first < cuts[p + 1];
                 t = nextToken(text, t.second, cuts[p + 1]), ++i) {
              double v;
              if (!readAsciiNumber(text.substr(t.first, t.second - t.first), v)) {
                bad[p] = t.first;
                badIndex[p] = i;
                break;
              }
              out[i] = T(v);
              pos = t.second;
            }
            reached[p] = pos;
          }
        },
        1);
    for (std::size_t p = 0; p < parts && first[p] < n; ++p) {
      // Values before the bad token are in place; the caller's parse goes on from it.
      if (bad[p] != kNone) return {badIndex[p], bad[p]};
      scan.end = reached[p];
    }
    scan.parsed = std::min(index, n);
    passed(scan.end);
  }
  return scan;
}

template AsciiScan parseAsciiNumbers<float>(std::string_view, std::size_t, std::size_t, float*,
                                            const std::function<void(std::size_t)>&,
                                            const AsciiWindows&);
template AsciiScan parseAsciiNumbers<double>(std::string_view, std::size_t, std::size_t, double*,
                                             const std::function<void(std::size_t)>&,
                                             const AsciiWindows&);

}  // namespace sandstorm
