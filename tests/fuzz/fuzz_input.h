// Helpers for the libFuzzer targets: the input as a file of a given name in a
// folder of this process's own (parsers that read files get a real file), and
// the input as text. Every target refuses bad input with sandstorm::Error and
// nothing else: any other exception escapes and the fuzzer reports it.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace sandstorm::fuzz {

inline std::filesystem::path scratch() {
  static const std::filesystem::path dir = [] {
    const auto d =
        std::filesystem::temp_directory_path() / ("sandstorm-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

inline std::filesystem::path asFile(const std::uint8_t* data, std::size_t size,
                                    const std::string& name) {
  const std::filesystem::path path = scratch() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Several files in one input, each after a line "//@ NAME": those whose NAME
// is in `allowed` are written under `root` (emptied first), the others ignored,
// so a fuzzer writes nowhere else.
template <class Names>
void asFiles(std::string_view text, const std::filesystem::path& root, const Names& allowed) {
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root);
  std::size_t at = text.rfind("//@ ", 0) == 0 ? 0 : text.find("\n//@ ");
  if (at != std::string_view::npos && at > 0) ++at;
  while (at != std::string_view::npos) {
    const std::size_t eol = text.find('\n', at);
    if (eol == std::string_view::npos) break;
    const std::string name(text.substr(at + 4, eol - at - 4));
    const std::size_t next = text.find("\n//@ ", eol);
    const std::string_view body =
        text.substr(eol + 1, next == std::string_view::npos ? std::string_view::npos : next - eol);
    for (const char* a : allowed)
      if (name == a) {
        const std::filesystem::path path = root / name;
        std::filesystem::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary | std::ios::trunc)
            .write(body.data(), std::streamsize(body.size()));
      }
    at = next == std::string_view::npos ? next : next + 1;
  }
}

// Loaders run with this budget: enough for any seed, small enough that a
// refused allocation shows as a fuzzer's malloc limit, not as swapping.
constexpr std::size_t kBudget = std::size_t{64} << 20;

}  // namespace sandstorm::fuzz
