// FileIdentity: a file as a shared file system shows it to every host, its
// size and modification time, so that cluster ranks reading a series' steps
// themselves can check they read the file rank 0 read without sending or
// hashing its bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace sandstorm {

struct FileIdentity {
  bool present = false;       // false: the file could not be seen
  std::uint64_t size = 0;     // bytes
  std::int64_t modified = 0;  // last write time, in the file clock's nanoseconds

  // Never throws: a file that cannot be seen is not `present`.
  static FileIdentity of(const std::filesystem::path& file);

  bool operator==(const FileIdentity&) const = default;
  // "1600000 bytes, modified 2026-11-27 06:34:39.123456789 UTC" or "not found".
  std::string text() const;
};

}  // namespace sandstorm
