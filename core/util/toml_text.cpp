#include "core/util/toml_text.h"

#include <cstdint>
#include <optional>

#include "core/util/error.h"
#include "core/util/utf8.h"

namespace sandstorm {
namespace {

bool isTokenChar(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' ||
         c == '+' || c == '-' || c == '.' || c == ':';
}

int digitValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 99;
}

// The integer a token spells, if it is an integer literal: nullopt for any
// other token (floats, dates, booleans, malformed ones toml11 will refuse).
// `fits` is false when it is an integer beyond the 64-bit range.
struct Literal {
  bool integer = false;
  bool fits = true;
};

Literal classify(std::string_view token) {
  Literal result;
  bool negative = false;
  std::size_t i = 0;
  if (!token.empty() && (token[0] == '+' || token[0] == '-')) negative = token[0] == '-', i = 1;
  int base = 10;
  if (token.size() > i + 1 && token[i] == '0' &&
      (token[i + 1] == 'x' || token[i + 1] == 'o' || token[i + 1] == 'b')) {
    base = token[i + 1] == 'x' ? 16 : token[i + 1] == 'o' ? 8 : 2;
    i += 2;
  }
  if (i >= token.size()) return result;
  // Magnitudes up to 2^63 (the size of the most negative integer).
  const std::uint64_t limit = std::uint64_t(1) << 63;
  std::uint64_t value = 0;
  bool overflow = false, digits = false;
  for (; i < token.size(); ++i) {
    if (token[i] == '_') continue;
    const int d = digitValue(token[i]);
    if (d >= base) return result;  // a float, a date, a word: not an integer
    digits = true;
    if (value > (limit - std::uint64_t(d)) / std::uint64_t(base))
      overflow = true;
    else
      value = value * std::uint64_t(base) + std::uint64_t(d);
  }
  if (!digits) return result;
  result.integer = true;
  result.fits = !overflow && (negative ? value <= limit : value < limit);
  return result;
}

class Scanner {
 public:
  Scanner(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  void run() {
    // True where a value may start: after '=', and after '[' or ',' (arrays).
    bool valueNext = false;
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (c == '\n') {
        ++line_, ++i_;
      } else if (c == '#') {
        while (i_ < text_.size() && text_[i_] != '\n')
          ++i_;
      } else if (c == '"' || c == '\'') {
        skipString(c);
        valueNext = false;
      } else if (c == '=' || c == '[' || c == ',' || c == '{') {
        valueNext = c != '{';
        if (c == '[' || c == '{') open();
        ++i_;
      } else if (c == ']' || c == '}') {
        if (depth_ > 0) --depth_;
        valueNext = false;
        ++i_;
      } else if (c == ' ' || c == '\t' || c == '\r') {
        ++i_;
      } else if (isTokenChar(c)) {
        const std::size_t start = i_;
        while (i_ < text_.size() && isTokenChar(text_[i_]))
          ++i_;
        if (valueNext) check(text_.substr(start, i_ - start));
        valueNext = false;
      } else {
        valueNext = false;
        ++i_;
      }
    }
  }

 private:
  void check(std::string_view token) const {
    const Literal literal = classify(token);
    if (literal.integer && !literal.fits)
      throw Error(concat(
          name_, ":", line_, ": the integer ", token.substr(0, 80), token.size() > 80 ? "..." : "",
          " does not fit in 64 bits; expected -9223372036854775808..", "9223372036854775807"));
  }

  // toml11 parses nested arrays and inline tables by recursion: a few
  // thousand levels overflow the stack.
  void open() {
    if (++depth_ > kMaxDepth)
      throw Error(concat(name_, ":", line_, ": arrays and inline tables nested more than ",
                         kMaxDepth, " deep; expected at most ", kMaxDepth,
                         " levels of [ ] and { }"));
  }

  // Skips a basic ("...", """...""") or literal ('...', '''...''') string.
  void skipString(char quote) {
    const bool multi = text_.substr(i_, 3) == std::string(3, quote);
    i_ += multi ? 3 : 1;
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (c == '\n') {
        ++line_;
        if (!multi) return;  // toml11 reports the unterminated string
      }
      if (c == '\\' && quote == '"') {
        i_ += 2;
        continue;
      }
      if (c == quote && (!multi || text_.substr(i_, 3) == std::string(3, quote))) {
        i_ += multi ? 3 : 1;
        // A multi-line string may end with up to two more quotes.
        while (multi && i_ < text_.size() && text_[i_] == quote)
          ++i_;
        return;
      }
      ++i_;
    }
  }

  std::string_view text_;
  const std::string& name_;
  std::size_t i_ = 0;
  std::size_t line_ = 1;
  int depth_ = 0;
  static constexpr int kMaxDepth = 32;
};

}  // namespace

void checkTomlText(std::string_view text, const std::string& name) {
  checkUtf8(text, name);
  Scanner(text, name).run();
}

std::string tomlString(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace sandstorm
