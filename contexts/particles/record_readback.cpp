#include "contexts/particles/record_readback.h"

#include <epoxy/gl.h>

#include "contexts/gl/objects.h"

namespace sandstorm {

std::vector<glm::vec4> readRecords(std::uint32_t buffer, std::size_t count) {
  std::vector<glm::vec4> records(count);
  if (count == 0) return records;
  const GLsizeiptr bytes = GLsizeiptr(count * sizeof(glm::vec4));
  gl::Buffer staging = gl::createBuffer();
  glNamedBufferStorage(staging.id(), bytes, nullptr, GL_CLIENT_STORAGE_BIT);
  glCopyNamedBufferSubData(buffer, staging.id(), 0, 0, bytes);
  glGetNamedBufferSubData(staging.id(), 0, bytes, records.data());
  return records;
}

}  // namespace sandstorm
