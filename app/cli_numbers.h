// Checks for the command lines' numeric options that say what a number must
// be in words ("a whole number, 0 or more; got '-3'"). CLI11's own
// NonNegativeNumber and PositiveNumber name a range whose end is the largest
// double, written out in 309 digits. Header-only: sandstorm and
// sandstorm-field share it (the tracker simulator's options have finite
// ranges, which CLI11 words well enough).
#pragma once

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace sandstorm {

// A whole number (an optional sign, then digits only) of at least `least`,
// and at most `most` (the options it checks are ints).
inline CLI::Validator wholeNumberCheck(long long least,
                                       long long most = std::numeric_limits<int>::max()) {
  const std::string expected = "a whole number, " + std::to_string(least) + " or more";
  return CLI::Validator(
      [expected, least, most](std::string& text) -> std::string {
        const std::string got = "; got '" + text + "'";
        if (text.empty() || text.find_first_not_of("+-0123456789") != std::string::npos)
          return "expected " + expected + got;
        errno = 0;
        char* end = nullptr;
        const long long v = std::strtoll(text.c_str(), &end, 10);
        if (end != text.c_str() + text.size() || (errno != 0 && errno != ERANGE) || v < least)
          return "expected " + expected + got;
        if (errno == ERANGE || v > most) return "expected at most " + std::to_string(most) + got;
        return {};
      },
      expected);
}

// A finite number greater than 0.
inline CLI::Validator positiveNumberCheck() {
  const std::string expected = "a number greater than 0";
  return CLI::Validator(
      [expected](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || errno != 0 || end != text.c_str() + text.size() || !std::isfinite(v) ||
            v <= 0.0)
          return "expected " + expected + "; got '" + text + "'";
        return {};
      },
      expected);
}

}  // namespace sandstorm
