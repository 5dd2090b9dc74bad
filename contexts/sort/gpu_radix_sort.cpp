#include "contexts/sort/gpu_radix_sort.h"

#include <algorithm>

#include <epoxy/gl.h>

namespace sandstorm {
namespace {

constexpr GLuint kRowGroups = 32768;  // workgroups a row of a 2D dispatch

void dispatchBlocks(GLuint program, std::uint32_t blocks) {
  const GLuint row = std::min<GLuint>(std::max<GLuint>(blocks, 1), kRowGroups);
  glProgramUniform1ui(program, 2, row);
  glDispatchCompute(row, (std::max<GLuint>(blocks, 1) + row - 1) / row, 1);
}

}  // namespace

GpuRadixSort::GpuRadixSort()
    : histogram_({"radix_histogram.comp"}),
      scan_({"radix_scan.comp"}),
      scatter_({"radix_scatter.comp"}),
      count_(gl::createBuffer()) {
  glNamedBufferStorage(count_.id(), 4, nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void GpuRadixSort::reserve(std::size_t capacity) {
  capacity = std::max<std::size_t>(capacity, 1);
  if (capacity <= capacity_) return;
  capacity_ = capacity;
  blocks_ = std::uint32_t((capacity + kBlock - 1) / kBlock);
  scratchKeys_ = gl::createBuffer();
  scratchValues_ = gl::createBuffer();
  table_ = gl::createBuffer();
  glNamedBufferStorage(scratchKeys_.id(), GLsizeiptr(capacity * 4), nullptr, 0);
  glNamedBufferStorage(scratchValues_.id(), GLsizeiptr(capacity * 4), nullptr, 0);
  glNamedBufferStorage(table_.id(), GLsizeiptr(std::size_t(blocks_) * 16 * 4), nullptr, 0);
}

void GpuRadixSort::sort(std::uint32_t keys, std::uint32_t values, std::uint32_t count) {
  if (count < 2) return;
  reserve(count);
  glNamedBufferSubData(count_.id(), 0, 4, &count);
  run(keys, values);
}

void GpuRadixSort::sortCounted(std::uint32_t keys, std::uint32_t values, std::size_t capacity,
                               std::uint32_t countBuffer, std::size_t countOffset) {
  if (capacity < 2) return;
  reserve(capacity);
  glCopyNamedBufferSubData(countBuffer, count_.id(), GLintptr(countOffset), 0, 4);
  run(keys, values);
}

void GpuRadixSort::run(std::uint32_t keys, std::uint32_t values) {
  // The table is as wide as the capacity's blocks; the shaders read the count.
  for (const gl::Program* p : {&histogram_, &scan_, &scatter_})
    glProgramUniform1ui(p->id(), 1, blocks_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, count_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, table_.id());
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  std::uint32_t inKeys = keys, inValues = values;
  std::uint32_t outKeys = scratchKeys_.id(), outValues = scratchValues_.id();
  for (int shift = 0; shift < 32; shift += kDigitBits) {
    histogram_.use();
    glProgramUniform1ui(histogram_.id(), 0, GLuint(shift));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, inKeys);
    dispatchBlocks(histogram_.id(), blocks_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    scan_.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    scatter_.use();
    glProgramUniform1ui(scatter_.id(), 0, GLuint(shift));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, inValues);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, outKeys);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, outValues);
    dispatchBlocks(scatter_.id(), blocks_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    std::swap(inKeys, outKeys);
    std::swap(inValues, outValues);
  }
  // Eight passes: the sorted keys are back in `keys`.
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

}  // namespace sandstorm
