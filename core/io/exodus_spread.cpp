#include "core/io/exodus_spread.h"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr int kMaxRanks = 65536;

// A run of decimal digits (at most 6) as a number; none otherwise.
std::optional<int> digits(const std::string& s) {
  if (s.empty() || s.size() > 6 ||
      !std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); }))
    return std::nullopt;
  return std::stoi(s);
}

}  // namespace

std::optional<ExodusSpreadName> parseExodusSpreadName(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  const std::size_t last = name.rfind('.');
  if (last == std::string::npos || last == 0) return std::nullopt;
  const std::size_t middle = name.rfind('.', last - 1);
  if (middle == std::string::npos || middle == 0) return std::nullopt;
  const std::optional<int> count = digits(name.substr(middle + 1, last - middle - 1));
  const std::optional<int> rank = digits(name.substr(last + 1));
  if (!count || !rank || *count < 2 || *count > kMaxRanks || *rank >= *count) return std::nullopt;
  return ExodusSpreadName{path.parent_path() / name.substr(0, middle), *count, *rank};
}

std::vector<std::filesystem::path> exodusRunFiles(const std::filesystem::path& path) {
  const std::optional<ExodusSpreadName> spread = parseExodusSpreadName(path);
  if (!spread) return {path};
  const std::string base = spread->base.string();
  const std::size_t width = std::to_string(spread->count).size();
  std::vector<std::filesystem::path> files;
  for (int r = 0; r < spread->count; ++r) {
    std::string rank = std::to_string(r);
    const std::string padded = std::string(width - rank.size(), '0') + rank;
    std::filesystem::path file = concat(base, ".", spread->count, ".", padded);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) {
      const std::filesystem::path plain = concat(base, ".", spread->count, ".", rank);
      if (!std::filesystem::is_regular_file(plain, ec))
        throw Error(concat(path.string(), ": one of a decomposed Exodus II run's ", spread->count,
                           " files (", spread->base.filename().string(), ".", spread->count,
                           ".0 .. ", spread->count - 1, "), but rank ", r, "'s file ",
                           file.filename().string(), " is missing"));
      file = plain;
    }
    files.push_back(file);
  }
  return files;
}

}  // namespace sandstorm
