// checkVdbGrid(): see vdb_file_check.h. The walk follows OpenVDB 10's readers
// (io::Archive::readGrid, MetaMap::readMeta, math::Transform::read, the 5-4-3
// tree's readTopology and readBuffers, io::readCompressedValues) step by step,
// reading sizes and masks but never values.
#include <algorithm>
#include <bit>
#include <cstring>
#include <set>
#include <tuple>
#include <vector>

#include <blosc.h>
#include <zlib.h>

#include "core/io/budget_advice.h"
#include "core/io/file_cursor.h"
#include "core/io/vdb_file_check.h"
#include "core/io/vdb_metadata_check.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr std::uint32_t kZip = 0x1, kActiveMask = 0x2, kBlosc = 0x4;
constexpr std::uint32_t kNodeMaskCompression = 222;

// One node level's layout: values per node, and their mask in bytes.
struct Level {
  std::uint32_t values;
  std::uint32_t maskBytes() const { return values / 8; }
};
constexpr Level kRootChild{32768};             // InternalNode<..., 5>: 32^3
constexpr Level kInner{4096};                  // InternalNode<..., 4>: 16^3
constexpr Level kLeaf{512};                    // LeafNode<..., 3>: 8^3
constexpr std::int32_t kRootChildSpan = 4096;  // voxels a root child spans per axis

class GridWalk {
 public:
  GridWalk(std::ifstream& in, const VdbGridEntry& grid, std::string file, std::uint32_t version,
           std::size_t budget)
      : c_(in, grid.endPos, file, "grid '" + grid.name + "'"),
        file_(std::move(file)),
        name_(grid.name),
        version_(version),
        budget_(budget) {
    c_.seek(grid.gridPos);
    std::string type = grid.type;
    const std::string half = "_HalfFloat";
    if (type.size() > half.size() && type.ends_with(half)) {
      fromHalf_ = true;
      type.resize(type.size() - half.size());
    }
    if (type == "Tree_vec3s_5_4_3")
      valueSize_ = 12;
    else if (type == "Tree_vec3d_5_4_3")
      valueSize_ = 24;
    else if (type == "Tree_float_5_4_3")
      valueSize_ = 4;
    else if (type == "Tree_double_5_4_3")
      valueSize_ = 8;
    else
      fail(concat("its tree type '", grid.type,
                  "' is not one Sandstorm reads (Tree_vec3s_5_4_3, Tree_vec3d_5_4_3, "
                  "Tree_float_5_4_3 or Tree_double_5_4_3)"));
    // Half floats are stored at 2 bytes a component: a vec3 in 6, a scalar in 2.
    halfSize_ = valueSize_ >= 12 ? 6 : 2;
  }

  // The grid's compression, metadata and transform; then, unless it is an instance, its tree.
  void run(bool instance) {
    if (version_ >= kNodeMaskCompression) flags_ = c_.value<std::uint32_t>("compression flags");
    if (flags_ & ~(kZip | kActiveMask | kBlosc))
      fail(concat("compression flags ", flags_, " name no compression OpenVDB knows"));
    metadata();
    transform(0);
    if (instance) return;
    const auto buffers = c_.value<std::int32_t>("tree buffer count");
    if (buffers != 1) fail(concat("a tree with ", buffers, " buffers; expected 1"));
    root();
    for (std::uint64_t i = 0; i < leaves_; ++i)
      leafBuffer();
    if (c_.left() != 0)
      fail(concat(c_.left(),
                  " bytes are left after the tree; the grid's layout is not what "
                  "its counts say"));
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(concat(file_, ": grid '", name_, "' at byte ", c_.offset(), ": ", what));
  }

  void metadata() { checkVdbMetadata(c_, concat(file_, ": grid '", name_, "' metadata")); }

  void transform(int depth) {
    const std::string type = c_.string("transform type");
    static const std::pair<const char*, std::uint64_t> sizes[] = {
        {"AffineMap", 128},
        {"UnitaryMap", 128},
        {"ScaleMap", 120},
        {"UniformScaleMap", 120},
        {"TranslationMap", 24},
        {"ScaleTranslateMap", 144},
        {"UniformScaleTranslateMap", 144}};
    for (const auto& [t, bytes] : sizes)
      if (type == t) return c_.skip(bytes, "transform");
    if (type == "NonlinearFrustumMap" && depth == 0) {
      c_.skip(48 + 16, "frustum bounds, taper and depth");
      return transform(depth + 1);
    }
    fail(concat("transform '", type.substr(0, 40), "' is not a map OpenVDB reads here"));
  }

  // io::readCompressedValues for `level` nodes whose value mask is `mask`.
  // `unpack`: decompress the values as OpenVDB will, and refuse what it would
  // fail on (internal nodes: OpenVDB leaks a node whose values fail).
  void compressedValues(const Level& level, const std::vector<std::uint8_t>& mask, const char* what,
                        bool unpack = false) {
    std::int8_t meta = 6;  // NO_MASK_AND_ALL_VALS
    if (version_ >= kNodeMaskCompression) meta = c_.value<std::int8_t>("value compression tag");
    if (meta < 0 || meta > 6)
      fail(concat(what, ": value compression tag ", int(meta), "; expected 0..6"));
    if (meta == 2 || meta == 4 || meta == 5) c_.skip(valueSize_, "inactive value");
    if (meta == 5) c_.skip(valueSize_, "second inactive value");
    if (meta == 3 || meta == 4 || meta == 5) c_.skip(level.maskBytes(), "selection mask");
    std::uint64_t count = level.values;
    if ((flags_ & kActiveMask) && meta != 6 && version_ >= kNodeMaskCompression) {
      count = 0;
      for (std::uint8_t b : mask)
        count += std::uint64_t(std::popcount(b));
    }
    const std::uint64_t bytes = count * (fromHalf_ ? halfSize_ : valueSize_);
    if (flags_ & (kZip | kBlosc)) {
      const auto stored = c_.value<std::int64_t>("compressed size");
      if (stored <= 0) {
        // A non-positive size says the values are stored raw; negate in
        // unsigned arithmetic, as INT64_MIN has no signed negation.
        const std::uint64_t raw = std::uint64_t(0) - std::uint64_t(stored);
        if (raw != bytes)
          fail(concat(what, ": ", raw, " uncompressed bytes for ", count, " values of ",
                      bytes / std::max<std::uint64_t>(count, 1), " bytes"));
        c_.skip(bytes, "values");
      } else if (unpack || (flags_ & kBlosc)) {
        if (std::uint64_t(stored) > c_.left())
          fail(concat(what, ": ", stored, " compressed bytes; ", c_.left(), " are left"));
        std::vector<char> packed(std::size_t(stored), '\0');
        c_.read(packed.data(), packed.size(), "compressed values");
        if (flags_ & kBlosc) {
          // Blosc trusts its chunk's header for every offset it reads: the
          // header must describe this chunk and these values, or OpenVDB's
          // decompression reads outside the chunk.
          std::size_t nbytes = 0;
          if (packed.size() < 16 ||
              blosc_cbuffer_validate(packed.data(), packed.size(), &nbytes) != 0 || nbytes != bytes)
            fail(concat(what, ": its blosc chunk (", stored, " bytes) does not describe the ",
                        bytes, " bytes of its ", count, " values"));
        }
        if (unpack) {
          std::vector<char> values(bytes ? bytes : 1);
          std::uint64_t got = 0;
          if (flags_ & kBlosc) {
            const int n = blosc_decompress_ctx(packed.data(), values.data(), values.size(), 1);
            got = n > 0 ? std::uint64_t(n) : 0;
          } else {
            uLongf length = uLongf(values.size());
            if (::uncompress(reinterpret_cast<Bytef*>(values.data()), &length,
                             reinterpret_cast<const Bytef*>(packed.data()),
                             uLong(packed.size())) == Z_OK)
              got = length;
          }
          if (got != bytes)
            fail(concat(what, ": its ", stored, " compressed bytes do not unpack to the ", bytes,
                        " bytes of its ", count, " values"));
        }
      } else {
        c_.skip(std::uint64_t(stored), "compressed values");
      }
    } else {
      c_.skip(bytes, "values");
    }
  }

  std::vector<std::uint8_t> mask(const Level& level, const char* what) {
    std::vector<std::uint8_t> m(level.maskBytes());
    c_.read(m.data(), m.size(), what);
    return m;
  }

  void reserve(double bytes) {
    nodeBytes_ += bytes;
    if (nodeBytes_ > double(budget_))
      fail(concat("its tree's nodes need more than ", nodeBytes_,
                  " bytes, beyond the memory budget (field.memory_budget) of ", budget_, " bytes",
                  raiseBudget(nodeBytes_)));
  }

  void root() {
    c_.skip(valueSize_, "background value");
    const auto tiles = c_.value<std::uint32_t>("root tile count");
    const auto children = c_.value<std::uint32_t>("root child count");
    const std::uint64_t tileBytes = 12 + valueSize_ + 1;
    const std::uint64_t childBytes = 12 + 2 * kRootChild.maskBytes() + 1;
    if (double(tiles) * double(tileBytes) + double(children) * double(childBytes) >
        double(c_.left()))
      fail(concat(tiles, " root tiles and ", children, " children cannot fit in the ", c_.left(),
                  " bytes left"));
    std::set<std::tuple<std::int32_t, std::int32_t, std::int32_t>> origins;
    const auto origin = [&](const char* what) {
      std::int32_t v[3];
      c_.read(v, sizeof v, what);
      for (std::int32_t x : v)
        if (x % kRootChildSpan != 0)
          fail(concat("a root ", what, " at (", v[0], ", ", v[1], ", ", v[2],
                      ") is not on the 4096-voxel grid of root entries"));
      if (!origins.emplace(v[0], v[1], v[2]).second)
        fail(concat("two root entries at (", v[0], ", ", v[1], ", ", v[2], ")"));
    };
    for (std::uint32_t i = 0; i < tiles; ++i) {
      origin("tile origin");
      c_.skip(valueSize_, "tile value");
      const auto active = c_.value<std::uint8_t>("tile state");
      if (active > 1) fail(concat("a tile state of ", int(active), "; expected 0 or 1"));
    }
    for (std::uint32_t i = 0; i < children; ++i) {
      origin("child origin");
      internal(kRootChild, true);
    }
  }

  // InternalNode::readTopology; `upper`: the 32^3 level (its children are 16^3 nodes).
  void internal(const Level& level, bool upper) {
    reserve(double(level.values) * 16.0);  // the node's table
    const std::vector<std::uint8_t> children = mask(level, "child mask");
    const std::vector<std::uint8_t> values = mask(level, "value mask");
    compressedValues(level, values, upper ? "an upper internal node" : "a lower internal node",
                     true);
    std::uint64_t count = 0;
    for (std::uint8_t b : children)
      count += std::uint64_t(std::popcount(b));
    // Each child's topology takes at least its two masks (or a leaf's one).
    const std::uint64_t least = upper ? 2 * kInner.maskBytes() + 1 : kLeaf.maskBytes();
    if (double(count) * double(least) > double(c_.left()))
      fail(concat(count, " child nodes cannot fit in the ", c_.left(), " bytes left"));
    for (std::uint64_t i = 0; i < count; ++i) {
      if (upper) {
        internal(kInner, false);
      } else {
        c_.skip(kLeaf.maskBytes(), "leaf value mask");
        reserve(double(kLeaf.values) * double(valueSize_) + 200.0);
        ++leaves_;
      }
    }
  }

  // LeafNode::readBuffers: the mask again, then the values it selects.
  void leafBuffer() {
    const std::vector<std::uint8_t> m = mask(kLeaf, "leaf value mask");
    compressedValues(kLeaf, m, "a leaf");
  }

  FileCursor c_;
  std::string file_, name_;
  std::uint32_t version_;
  std::size_t budget_;
  std::uint64_t valueSize_ = 12;
  std::uint64_t halfSize_ = 6;
  bool fromHalf_ = false;
  std::uint32_t flags_ = 0;
  std::uint64_t leaves_ = 0;
  double nodeBytes_ = 0.0;
};

}  // namespace

void checkVdbGrid(const std::filesystem::path& path, const std::vector<VdbGridEntry>& grids,
                  std::size_t index, std::size_t memoryBudget) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(file, ": cannot open the file for reading"));
  std::uint32_t version = 0;
  in.seekg(8);
  in.read(reinterpret_cast<char*>(&version), 4);
  const VdbGridEntry& grid = grids.at(index);
  const bool instance = !grid.instanceParent.empty();
  GridWalk(in, grid, file, version, memoryBudget).run(instance);
  if (!instance) return;
  // An instance shares its parent's tree: walk that.
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (grids[i].name == grid.instanceParent && grids[i].instanceParent.empty()) {
      GridWalk(in, grids[i], file, version, memoryBudget).run(false);
      return;
    }
  throw Error(concat(file, ": grid '", grid.name, "' is an instance of '", grid.instanceParent,
                     "', which the file does not hold"));
}

}  // namespace sandstorm
