#include "core/io/vdb_file_check.h"

#include <cstdint>
#include <cstring>
#include <fstream>

#include "core/util/error.h"

namespace sandstorm {
namespace {

class Cursor {
 public:
  Cursor(std::ifstream& in, std::uint64_t size, std::string file)
      : in_(in), size_(size), file_(std::move(file)) {}

  std::uint64_t offset() const { return offset_; }
  std::uint64_t left() const { return size_ - offset_; }

  void read(void* out, std::uint64_t n, const char* what) {
    if (n > left())
      throw Error(concat(file_, ": truncated at byte ", size_, " while reading the ", what,
                         " at byte ", offset_, " (", n, " bytes needed)"));
    in_.read(static_cast<char*>(out), std::streamsize(n));
    if (!in_) throw Error(concat(file_, ": read error at byte ", offset_));
    offset_ += n;
  }
  template <class T>
  T value(const char* what) {
    T v{};
    read(&v, sizeof(T), what);
    return v;
  }
  void skip(std::uint64_t n, const char* what) {
    if (n > left())
      throw Error(concat(file_, ": truncated at byte ", size_, " inside the ", what,
                         " that starts at byte ", offset_, " (", n, " bytes declared)"));
    seek(offset_ + n);
  }
  std::string string(const char* what) {
    const auto n = value<std::uint32_t>(what);
    if (n > left())
      throw Error(concat(file_, ": the ", what, " at byte ", offset_ - 4, " declares ", n,
                         " bytes, more than the ", left(), " left in the file"));
    std::string s(n, '\0');
    if (n) read(s.data(), n, what);
    return s;
  }
  void seek(std::uint64_t to) {
    in_.seekg(std::streamoff(to));
    offset_ = to;
  }

 private:
  std::ifstream& in_;
  std::uint64_t size_;
  std::string file_;
  std::uint64_t offset_ = 0;
};

}  // namespace

std::vector<VdbGridEntry> checkVdbFile(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(file, ": cannot open the file for reading"));
  const std::uint64_t size = std::filesystem::file_size(path);
  Cursor c(in, size, file);

  if (c.value<std::int64_t>("magic number") != 0x56444220)
    throw Error(concat(file, ": not an OpenVDB file (no 'VDB ' magic number)"));
  const auto version = c.value<std::uint32_t>("file version");
  if (version < 222 || version > 300)
    throw Error(concat(file, ": OpenVDB file format version ", version,
                       " is not supported; expected 222 (OpenVDB 3) or later. Re-save the file "
                       "with a current OpenVDB"));
  c.skip(8, "library version");
  const char hasOffsets = c.value<char>("grid offset flag");
  if (!hasOffsets)
    throw Error(concat(file,
                       ": was written as a stream without grid offsets; re-save it with "
                       "openvdb::io::File"));
  c.skip(36, "UUID");
  const auto metaCount = c.value<std::uint32_t>("file metadata count");
  if (metaCount > c.left() / 12)
    throw Error(concat(file, ": declares ", metaCount,
                       " metadata entries, more than the file "
                       "can hold"));
  for (std::uint32_t i = 0; i < metaCount; ++i) {
    c.string("metadata name");
    c.string("metadata type");
    c.skip(c.value<std::uint32_t>("metadata size"), "metadata value");
  }
  const auto gridCount = c.value<std::int32_t>("grid count");
  if (gridCount < 0 || std::uint64_t(gridCount) > c.left() / 40)
    throw Error(concat(file, ": declares ", gridCount, " grids, which the file cannot hold"));

  std::vector<VdbGridEntry> grids;
  for (std::int32_t i = 0; i < gridCount; ++i) {
    VdbGridEntry entry;
    entry.name = c.string("grid name");
    entry.type = c.string("grid type");
    c.string("grid instance parent");
    const auto gridPos = c.value<std::int64_t>("grid position");
    const auto blockPos = c.value<std::int64_t>("grid data position");
    const auto endPos = c.value<std::int64_t>("grid end position");
    if (gridPos != std::int64_t(c.offset()) || blockPos < gridPos || endPos < blockPos ||
        std::uint64_t(endPos) > size)
      throw Error(concat(file, ": grid '", entry.name, "' spans bytes ", gridPos, " to ", endPos,
                         " but the file has ", size, " bytes; the file is truncated or damaged"));
    c.seek(std::uint64_t(endPos));
    grids.push_back(std::move(entry));
  }
  if (grids.empty()) throw Error(concat(file, ": holds no grids"));
  return grids;
}

}  // namespace sandstorm
