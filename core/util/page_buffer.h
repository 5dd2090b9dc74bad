// PageBuffer: a file's bytes in anonymous memory pages whose front can be
// given back to the system while the rest is still in use. A parser that
// walks a large file front to back (the legacy VTK parser) holds the text
// it has not yet passed, not the whole file beside the arrays it makes.
// Pages given back read as zeros: only bytes at or after released() may be
// read. Move-only; throws Error naming the file where the pages cannot be had.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace sandstorm {

class PageBuffer {
 public:
  PageBuffer() = default;
  PageBuffer(std::size_t size, const std::string& file);
  ~PageBuffer();
  PageBuffer(PageBuffer&& other) noexcept;
  PageBuffer& operator=(PageBuffer&& other) noexcept;
  PageBuffer(const PageBuffer&) = delete;
  PageBuffer& operator=(const PageBuffer&) = delete;

  char* data() { return data_; }
  std::size_t size() const { return size_; }
  std::string_view view() const { return {data_, size_}; }

  // The start of the page holding byte `offset`.
  static std::size_t pageFloor(std::size_t offset);
  // Gives back the whole pages before `offset`; returns the new released().
  std::size_t releaseBefore(std::size_t offset);
  std::size_t released() const { return released_; }

 private:
  char* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t mapped_ = 0;    // bytes mapped (size_ rounded up to a page)
  std::size_t released_ = 0;  // bytes at the front already given back
};

}  // namespace sandstorm
