// parseAsciiNumbers: whitespace-separated numbers (an ASCII legacy VTK
// file's values) parsed over the cores. The text is taken a window at a time;
// a window is cut into parts at whitespace, the parts' tokens are counted in
// parallel, which gives each part the index of its first value, and then
// parsed in parallel into their places. Each token is read exactly as
// readAsciiNumber reads it, so the result equals a serial parse's.
// Stops before the first token that is not a number, so that the caller's
// serial parse names it with its line; pure C++.
#pragma once

#include <cstddef>
#include <functional>
#include <string_view>

namespace sandstorm {

// The legacy parser's whitespace.
inline bool isAsciiSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

// `token` as a number (std::from_chars' double; a value out of double's
// range reads as 0, as before); false where it is not one.
bool readAsciiNumber(std::string_view token, double& value);

struct AsciiScan {
  std::size_t parsed = 0;  // values written to out[0 .. parsed)
  std::size_t end = 0;     // the offset in the text after the last of them
};

struct AsciiWindows {
  std::size_t window = std::size_t{32} << 20;  // bytes taken at a time
  std::size_t part = std::size_t{256} << 10;   // bytes a part, at least
};

// Up to n numbers from text[from ..] into out[0 .. n), each rounded to T
// from its double. `passed(offset)` hears after each window how far the
// values parsed reach, to report progress and give the text behind back.
template <class T>
AsciiScan parseAsciiNumbers(std::string_view text, std::size_t from, std::size_t n, T* out,
                            const std::function<void(std::size_t)>& passed,
                            const AsciiWindows& windows = {});

}  // namespace sandstorm
