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

// Loaders run with this budget: enough for any seed, small enough that a
// refused allocation shows as a fuzzer's malloc limit, not as swapping.
constexpr std::size_t kBudget = std::size_t{64} << 20;

}  // namespace sandstorm::fuzz
