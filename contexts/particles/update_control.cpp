#include "contexts/particles/update_control.h"

#include <epoxy/gl.h>

#include "core/util/error.h"

namespace sandstorm {

UpdateCounts::UpdateCounts(const char* owner) : buffer_(gl::createBuffer()) {
  const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
  const GLsizeiptr bytes = kSlots * sizeof(std::uint32_t);
  glNamedBufferStorage(buffer_.id(), bytes, nullptr, flags);
  map_ = static_cast<const std::uint32_t*>(glMapNamedBufferRange(buffer_.id(), 0, bytes, flags));
  if (!map_) throw Error(concat(owner, ": cannot map the count history buffer"));
}

void UpdateCounts::record(std::uint64_t update, std::uint32_t control, std::ptrdiff_t offset) {
  const std::size_t slot = std::size_t(update % kSlots);
  glCopyNamedBufferSubData(control, buffer_.id(), offset, GLintptr(slot * sizeof(std::uint32_t)),
                           sizeof(std::uint32_t));
  fences_[slot] = gl::createFence();
}

std::size_t UpdateCounts::after(std::uint64_t update) const {
  const std::size_t slot = std::size_t(update % kSlots);
  if (const gl::Sync& fence = fences_[slot]) {
    const GLsync sync = reinterpret_cast<GLsync>(fence.handle());
    while (glClientWaitSync(sync, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000) ==
           GL_TIMEOUT_EXPIRED) {
    }
  }
  return map_[slot];
}

}  // namespace sandstorm
