#include "core/io/vdb_file_check.h"

#include <cstdint>
#include <cstring>
#include <fstream>

#include "core/io/file_cursor.h"
#include "core/io/vdb_metadata_check.h"
#include "core/util/error.h"

namespace sandstorm {

std::vector<VdbGridEntry> checkVdbFile(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(file, ": cannot open the file for reading"));
  const std::uint64_t size = std::filesystem::file_size(path);
  FileCursor c(in, size, file);

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
  checkVdbMetadata(c, file + ": file metadata");
  const auto gridCount = c.value<std::int32_t>("grid count");
  if (gridCount < 0 || std::uint64_t(gridCount) > c.left() / 40)
    throw Error(concat(file, ": declares ", gridCount, " grids, which the file cannot hold"));

  std::vector<VdbGridEntry> grids;
  for (std::int32_t i = 0; i < gridCount; ++i) {
    VdbGridEntry entry;
    entry.name = c.string("grid name");
    entry.type = c.string("grid type");
    entry.instanceParent = c.string("grid instance parent");
    const auto gridPos = c.value<std::int64_t>("grid position");
    const auto blockPos = c.value<std::int64_t>("grid data position");
    const auto endPos = c.value<std::int64_t>("grid end position");
    // An instance shares its parent's tree: it has no data block of its own.
    const bool instance = !entry.instanceParent.empty();
    if (gridPos != std::int64_t(c.offset()) || endPos < gridPos ||
        (!instance && (blockPos < gridPos || endPos < blockPos)) || std::uint64_t(endPos) > size)
      throw Error(concat(file, ": grid '", entry.name, "' spans bytes ", gridPos, " (data at ",
                         blockPos, ") to ", endPos, " but the file has ", size,
                         " bytes; the file is truncated or damaged"));
    c.seek(std::uint64_t(endPos));
    entry.gridPos = std::uint64_t(gridPos);
    entry.blockPos = std::uint64_t(blockPos);
    entry.endPos = std::uint64_t(endPos);
    grids.push_back(std::move(entry));
  }
  if (grids.empty()) throw Error(concat(file, ": holds no grids"));
  return grids;
}

}  // namespace sandstorm
