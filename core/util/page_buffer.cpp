#include "core/util/page_buffer.h"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include "core/util/error.h"

namespace sandstorm {
namespace {

std::size_t pageSize() {
  static const std::size_t page = std::size_t(sysconf(_SC_PAGESIZE));
  return page;
}

}  // namespace

PageBuffer::PageBuffer(std::size_t size, const std::string& file) : size_(size) {
  if (size == 0) return;
  mapped_ = (size + pageSize() - 1) / pageSize() * pageSize();
  void* p = mmap(nullptr, mapped_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED)
    throw Error(concat(file, ": cannot have ", size,
                       " bytes of memory to read it into: ", std::strerror(errno)));
  data_ = static_cast<char*>(p);
}

PageBuffer::~PageBuffer() {
  if (data_) munmap(data_, mapped_);
}

PageBuffer::PageBuffer(PageBuffer&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)),
      size_(std::exchange(other.size_, 0)),
      mapped_(std::exchange(other.mapped_, 0)),
      released_(std::exchange(other.released_, 0)) {}

PageBuffer& PageBuffer::operator=(PageBuffer&& other) noexcept {
  if (this != &other) {
    if (data_) munmap(data_, mapped_);
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
    mapped_ = std::exchange(other.mapped_, 0);
    released_ = std::exchange(other.released_, 0);
  }
  return *this;
}

std::size_t PageBuffer::pageFloor(std::size_t offset) {
  return offset / pageSize() * pageSize();
}

std::size_t PageBuffer::releaseBefore(std::size_t offset) {
  const std::size_t end = pageFloor(std::min(offset, size_));
  if (end > released_) {
    // MADV_DONTNEED on private anonymous pages frees them at once; a later
    // read of them would see zeros, which is why released() is kept.
    madvise(data_ + released_, end - released_, MADV_DONTNEED);
    released_ = end;
  }
  return released_;
}

}  // namespace sandstorm
