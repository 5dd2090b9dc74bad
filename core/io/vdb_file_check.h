// checkVdbFile(): walks an OpenVDB file's header and grid descriptors before
// OpenVDB reads it, and lists its grids.
//
// OpenVDB trusts the counts and string lengths in a file: a truncated header
// can make it allocate gigabytes, and a file cut inside its last grid can load
// silently short. This walk checks, against the file's size, every string
// length and metadata size of the header, the grid count, and each grid's
// [start, end) byte range; anything out of range throws Error naming the file
// and the offset. Files written without grid offsets (io::Stream) are refused.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sandstorm {

struct VdbGridEntry {
  std::string name;            // as written (unique name, with a "[n]" suffix if repeated)
  std::string type;            // tree type, e.g. "Tree_vec3s_5_4_3"
  std::string instanceParent;  // a grid instance shares this grid's tree
  std::uint64_t gridPos = 0, blockPos = 0, endPos = 0;
};

std::vector<VdbGridEntry> checkVdbFile(const std::filesystem::path& path);

// checkVdbGrid(): walks one Vec3 grid (vec3s or vec3d, 5-4-3 tree, half or
// full floats) before openvdb::io::File::readGrid, as OpenVDB will read it:
// its compression flags, metadata, transform, the tree's topology (root tiles
// and children, internal nodes' masks and compressed values, leaf masks) and
// every leaf's buffer. Every count, string, metadata size, compressed block
// and node origin is checked against the bytes the grid spans, the tree's
// nodes against the memory budget, and the walk must end inside the grid.
// OpenVDB allocates what these claim before it notices a short file (and
// leaks half-read nodes when it then throws), so it reads only what passes.
void checkVdbGrid(const std::filesystem::path& path, const std::vector<VdbGridEntry>& grids,
                  std::size_t index, std::size_t memoryBudget);

}  // namespace sandstorm
