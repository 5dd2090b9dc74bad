// ByteReader: reads what ByteWriter wrote, checking every step. Running past
// the end, an oversized length or a bad value throws Error naming the buffer,
// the item being read and the offset, so a truncated or corrupt message is a
// clear error and never a crash.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>

#include "core/util/error.h"

namespace sandstorm {

class ByteReader {
 public:
  ByteReader(std::span<const std::byte> bytes, std::string name)
      : bytes_(bytes), name_(std::move(name)) {}

  std::uint8_t u8(std::string_view what) { return std::uint8_t(little(1, what)); }
  std::uint16_t u16(std::string_view what) { return std::uint16_t(little(2, what)); }
  std::uint32_t u32(std::string_view what) { return std::uint32_t(little(4, what)); }
  std::uint64_t u64(std::string_view what) { return little(8, what); }
  std::int32_t i32(std::string_view what) { return static_cast<std::int32_t>(u32(what)); }
  float f32(std::string_view what) { return std::bit_cast<float>(u32(what)); }
  double f64(std::string_view what) { return std::bit_cast<double>(u64(what)); }
  bool boolean(std::string_view what) {
    const std::uint8_t v = u8(what);
    if (v > 1) fail(what, concat("expected 0 or 1, got ", int(v)));
    return v == 1;
  }
  std::string str(std::string_view what, std::size_t maxLength) {
    const std::uint32_t n = u32(what);
    if (n > maxLength) fail(what, concat("length ", n, " exceeds the limit of ", maxLength));
    const std::span<const std::byte> b = raw(n, what);
    return std::string(reinterpret_cast<const char*>(b.data()), b.size());
  }
  std::span<const std::byte> raw(std::size_t n, std::string_view what) {
    need(n, what);
    const std::span<const std::byte> out = bytes_.subspan(offset_, n);
    offset_ += n;
    return out;
  }
  void f32s(std::span<float> out, std::string_view what) {
    const std::span<const std::byte> b = raw(out.size() * sizeof(float), what);
    if constexpr (std::endian::native == std::endian::little) {
      std::memcpy(out.data(), b.data(), b.size());
    } else {
      ByteReader inner(b, name_);
      for (float& v : out)
        v = inner.f32(what);
    }
  }

  void u16s(std::span<std::uint16_t> out, std::string_view what) {
    const std::span<const std::byte> b = raw(out.size() * sizeof(std::uint16_t), what);
    if constexpr (std::endian::native == std::endian::little) {
      std::memcpy(out.data(), b.data(), b.size());
    } else {
      ByteReader inner(b, name_);
      for (std::uint16_t& v : out)
        v = inner.u16(what);
    }
  }

  std::size_t offset() const { return offset_; }
  std::size_t remaining() const { return bytes_.size() - offset_; }
  // Throws unless every byte was read: trailing bytes mean a mismatched format.
  void finish() const {
    if (remaining() != 0)
      throw Error(
          concat(name_, ": ", remaining(), " unexpected bytes after the end at offset ", offset_));
  }
  [[noreturn]] void fail(std::string_view what, const std::string& why) const {
    throw Error(concat(name_, ": ", what, " at offset ", offset_, ": ", why));
  }

 private:
  void need(std::size_t n, std::string_view what) const {
    if (n > remaining())
      fail(what,
           concat("truncated: needs ", n, " bytes, ", remaining(), " left of ", bytes_.size()));
  }
  std::uint64_t little(int n, std::string_view what) {
    need(std::size_t(n), what);
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i)
      v |= std::uint64_t(std::to_integer<std::uint8_t>(bytes_[offset_ + std::size_t(i)]))
           << (8 * i);
    offset_ += std::size_t(n);
    return v;
  }

  std::span<const std::byte> bytes_;
  std::string name_;
  std::size_t offset_ = 0;
};

}  // namespace sandstorm
