#include "core/io/vdb_metadata_check.h"

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <blosc.h>

#include "core/util/error.h"

namespace sandstorm {
namespace {

class MetadataWalk {
 public:
  MetadataWalk(FileCursor& c, std::string where) : c_(c), where_(std::move(where)) {}

  void run() {
    const auto count = c_.value<std::uint32_t>("metadata count");
    if (count > c_.left() / 12) fail(concat(count, " metadata entries cannot fit"));
    // OpenVDB reads these types' values at their own size, whatever the entry says.
    static const std::pair<const char*, std::uint32_t> fixed[] = {
        {"bool", 1},   {"int32", 4},  {"int64", 8},  {"float", 4},  {"double", 8}, {"vec2i", 8},
        {"vec2s", 8},  {"vec2d", 16}, {"vec3i", 12}, {"vec3s", 12}, {"vec3d", 24}, {"vec4i", 16},
        {"vec4s", 16}, {"vec4d", 32}, {"mat4s", 64}, {"mat4d", 128}};
    for (std::uint32_t i = 0; i < count; ++i) {
      const std::string name = c_.string("metadata name");
      const std::string type = c_.string("metadata type");
      const auto size = c_.value<std::uint32_t>("metadata size");
      for (const auto& [t, bytes] : fixed)
        if (type == t && size != bytes)
          fail(concat("metadata '", name, "' of type ", type, " declares ", size,
                      " bytes; the type has ", bytes));
      if (type == "__delayedload")
        delayedLoad(name, size);
      else
        c_.skip(size, "metadata value");
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(concat(where_, " at byte ", c_.offset(), ": ", what));
  }

  // DelayedLoadMetadata::readValue: a count, then the mask (count bytes) and
  // the compressed sizes (count 8-byte values, or none), each after its
  // stored size (0: raw; else a blosc chunk of that many bytes).
  void delayedLoad(const std::string& name, std::uint32_t size) {
    if (size == 0) return;
    left_ = size;
    const auto count = std::uint64_t(field<std::uint32_t>(name, "count"));
    part(name, "mask", count, field<std::uint32_t>(name, "mask size"));
    const auto sizes = field<std::uint32_t>(name, "compressed sizes' size");
    if (sizes != std::numeric_limits<std::uint32_t>::max())
      part(name, "compressed sizes", count * 8, sizes);
    c_.skip(left_, "metadata value");
  }

  template <class T>
  T field(const std::string& name, const char* what) {
    need(name, sizeof(T), what);
    return c_.value<T>(what);
  }

  void need(const std::string& name, std::uint64_t bytes, const char* what) {
    if (bytes > left_)
      fail(concat("metadata '", name, "' (__delayedload): its ", what, " needs ", bytes,
                  " bytes; the entry has ", left_, " left"));
    left_ -= bytes;
  }

  // `bytes` of values, stored raw (`stored` 0) or as a blosc chunk of `stored` bytes.
  void part(const std::string& name, const char* what, std::uint64_t bytes, std::uint32_t stored) {
    if (stored == 0) {
      need(name, bytes, what);
      c_.skip(bytes, what);
      return;
    }
    need(name, stored, what);
    std::vector<char> chunk(stored);
    c_.read(chunk.data(), chunk.size(), what);
    // OpenVDB pads arrays under 128 bytes to 128 before compressing them.
    constexpr std::uint64_t kPadBytes = 128;
    std::size_t unpacked = 0;
    if (chunk.size() < 16 || blosc_cbuffer_validate(chunk.data(), chunk.size(), &unpacked) != 0 ||
        !(unpacked == bytes || (bytes < kPadBytes && unpacked == kPadBytes)))
      fail(concat("metadata '", name, "' (__delayedload): its ", what, " chunk (", stored,
                  " bytes) does not describe the ", bytes, " bytes of its count"));
  }

  FileCursor& c_;
  std::string where_;
  std::uint64_t left_ = 0;
};

}  // namespace

void checkVdbMetadata(FileCursor& cursor, const std::string& where) {
  MetadataWalk(cursor, where).run();
}

}  // namespace sandstorm
