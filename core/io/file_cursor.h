// FileCursor: reads a binary file front to back with every read and skip
// checked against an end (the file's size, or the end of one record inside
// it): running past it throws Error naming the file, the item and the offset.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>

#include "core/util/error.h"

namespace sandstorm {

class FileCursor {
 public:
  // `end`: the first byte not to read; `scope` names what ends there in messages.
  FileCursor(std::ifstream& in, std::uint64_t end, std::string file, std::string scope = "the file")
      : in_(in), size_(end), file_(std::move(file)), scope_(std::move(scope)) {}

  std::uint64_t offset() const { return offset_; }
  std::uint64_t left() const { return size_ - offset_; }

  void read(void* out, std::uint64_t n, const char* what) {
    if (n > left())
      throw Error(concat(file_, ": truncated: the ", what, " at byte ", offset_, " needs ", n,
                         " bytes; ", scope_, " ends at byte ", size_));
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
      throw Error(concat(file_, ": truncated: the ", what, " at byte ", offset_, " declares ", n,
                         " bytes; ", scope_, " ends at byte ", size_));
    seek(offset_ + n);
  }
  std::string string(const char* what) {
    const auto n = value<std::uint32_t>(what);
    if (n > left())
      throw Error(concat(file_, ": the ", what, " at byte ", offset_ - 4, " declares ", n,
                         " bytes, more than the ", left(), " left in ", scope_));
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
  std::string scope_;
  std::uint64_t offset_ = 0;
};

}  // namespace sandstorm
