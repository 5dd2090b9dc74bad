// ByteWriter: appends fixed-width little-endian numbers and length-prefixed
// strings to a byte buffer; the writing half of a wire format (ByteReader
// reads it back). Little-endian on every host, so ranks on different machines
// agree; floats travel as their IEEE bits, never as text, so they arrive exact.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <vector>

namespace sandstorm {

class ByteWriter {
 public:
  void u8(std::uint8_t v) { bytes_.push_back(std::byte{v}); }
  void u16(std::uint16_t v) { little(v, 2); }
  void u32(std::uint32_t v) { little(v, 4); }
  void u64(std::uint64_t v) { little(v, 8); }
  void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }
  void f32(float v) { u32(std::bit_cast<std::uint32_t>(v)); }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  void boolean(bool v) { u8(v ? 1 : 0); }
  // A u32 length, then the characters.
  void str(std::string_view s) {
    u32(static_cast<std::uint32_t>(s.size()));
    raw(std::as_bytes(std::span<const char>(s.data(), s.size())));
  }
  void raw(std::span<const std::byte> b) { bytes_.insert(bytes_.end(), b.begin(), b.end()); }
  // Floats in bulk (field grids): one copy where the host is little-endian.
  void f32s(std::span<const float> values) {
    if constexpr (std::endian::native == std::endian::little) {
      raw(std::as_bytes(values));
    } else {
      for (const float v : values)
        f32(v);
    }
  }

  // 16-bit words in bulk (half-precision grids), as f32s.
  void u16s(std::span<const std::uint16_t> values) {
    if constexpr (std::endian::native == std::endian::little) {
      raw(std::as_bytes(values));
    } else {
      for (const std::uint16_t v : values)
        u16(v);
    }
  }

  std::size_t size() const { return bytes_.size(); }
  const std::vector<std::byte>& bytes() const { return bytes_; }
  std::vector<std::byte> take() { return std::move(bytes_); }

 private:
  void little(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i)
      bytes_.push_back(std::byte(static_cast<std::uint8_t>(v >> (8 * i))));
  }

  std::vector<std::byte> bytes_;
};

}  // namespace sandstorm
