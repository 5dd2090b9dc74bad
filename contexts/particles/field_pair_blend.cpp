#include "contexts/particles/field_pair_blend.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "core/util/error.h"

namespace sandstorm {

void FieldPairBlend::blend(const GpuField& first, const GpuField& second, float weight) {
  const std::shared_ptr<const VectorField>& a = first.holds();
  const std::shared_ptr<const VectorField>& b = second.holds();
  if (!a || !b || first.storage() == GpuField::Storage::Texture ||
      second.storage() != first.storage() || a->dims() != b->dims())
    throw Error("FieldPairBlend: a pair of grids in one buffer layout is needed");
  const glm::ivec3 d = a->dims();
  const std::size_t points = std::size_t(d.x) * std::size_t(d.y) * std::size_t(d.z);
  const bool half = first.storage() == GpuField::Storage::HalfBuffer;
  const std::size_t bytes = points * (half ? 8 : 16);
  if (!program_ || storage_ != first.storage()) {
    program_ = std::make_unique<gl::Program>(
        std::vector<std::string>{"field_blend.comp"},
        half ? std::vector<std::string>{"FIELD_BUFFER_HALF"} : std::vector<std::string>{});
    storage_ = first.storage();
    forget();
  }
  if (bytes_ != bytes) {
    grid_.reset();  // the old one's memory back before the new one's is asked for
    glGetError();
    grid_ = gl::createBuffer();
    glNamedBufferStorage(grid_.id(), GLsizeiptr(bytes), nullptr, 0);
    if (glGetError() != GL_NO_ERROR) {
      grid_.reset();
      bytes_ = 0;
      throw Error(concat("a time-varying field's blend: no GPU memory for a ", d.x, "x", d.y, "x",
                         d.z, " grid (", bytes >> 20,
                         " MiB) beside its two steps; lower "
                         "field.resolution, or field.precision = \"half\""));
    }
    bytes_ = bytes;
    forget();
  }
  first.bind(GpuField::Slot::Current);
  second.bind(GpuField::Slot::Next);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 13, grid_.id());
  if (first_ == a && second_ == b && weight_ == weight) return;
  program_->use();
  glProgramUniform1f(program_->id(), 0, weight);
  glProgramUniform1ui(program_->id(), 1, std::uint32_t(points));
  // Enough workgroups to fill any GPU; each invocation strides over the rest.
  const GLuint groups = GLuint(std::clamp<std::size_t>((points + 255) / 256, 1, 4096));
  glDispatchCompute(groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  first_ = a;
  second_ = b;
  weight_ = weight;
}

}  // namespace sandstorm
