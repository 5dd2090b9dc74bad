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

#include <filesystem>
#include <string>
#include <vector>

namespace sandstorm {

struct VdbGridEntry {
  std::string name;  // as written (unique name, with a "[n]" suffix if repeated)
  std::string type;  // tree type, e.g. "Tree_vec3s_5_4_3"
};

std::vector<VdbGridEntry> checkVdbFile(const std::filesystem::path& path);

}  // namespace sandstorm
