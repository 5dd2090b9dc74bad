#include "core/config/byte_size.h"

#include <unistd.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <utility>

namespace sandstorm {

std::optional<std::uint64_t> parseByteSize(std::string_view text) {
  const auto trim = [](std::string_view s) {
    while (!s.empty() && std::isspace((unsigned char)s.front()))
      s.remove_prefix(1);
    while (!s.empty() && std::isspace((unsigned char)s.back()))
      s.remove_suffix(1);
    return s;
  };
  text = trim(text);
  std::size_t numberEnd = 0;
  while (numberEnd < text.size() &&
         (std::isdigit((unsigned char)text[numberEnd]) || text[numberEnd] == '.'))
    ++numberEnd;
  if (numberEnd == 0) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + numberEnd, value);
  if (ec != std::errc() || end != text.data() + numberEnd || !std::isfinite(value))
    return std::nullopt;
  const std::string_view unit = trim(text.substr(numberEnd));
  static const std::pair<std::string_view, double> units[] = {
      {"", 1.0},   {"B", 1.0},  {"KiB", 0x1p10}, {"MiB", 0x1p20}, {"GiB", 0x1p30}, {"TiB", 0x1p40},
      {"kB", 1e3}, {"KB", 1e3}, {"MB", 1e6},     {"GB", 1e9},     {"TB", 1e12}};
  for (const auto& [name, scale] : units)
    if (unit == name) {
      const double bytes = value * scale;
      if (bytes >= 0x1p63) return std::nullopt;
      return std::uint64_t(std::llround(bytes));
    }
  return std::nullopt;
}

std::string formatByteSize(double bytes) {
  static const char* names[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 4)
    bytes /= 1024.0, ++u;
  char text[48];
  std::snprintf(text, sizeof text, u == 0 ? "%.0f %s" : "%.3g %s", bytes, names[u]);
  return text;
}

std::uint64_t hostMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
  return pages > 0 && size > 0 ? std::uint64_t(pages) * std::uint64_t(size) : 0;
}

}  // namespace sandstorm
