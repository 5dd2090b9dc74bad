#include "contexts/particles/gpu_field.h"

#include <epoxy/gl.h>

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <string_view>
#include <thread>
#include <vector>

#include "core/util/error.h"
#include "core/util/parallel_for.h"

namespace sandstorm {

void GpuField::upload(const VectorField& field) {
  const auto start = std::chrono::steady_clock::now();
  // A half-precision grid is a 16-bit float texture (the buffer holds floats).
  const Storage storage =
      preferred_ == Storage::Buffer && !field.halfPrecision() && fitsBuffer(field)
          ? Storage::Buffer
          : Storage::Texture;
  if (storage != storage_) {
    texture_ = {};
    buffer_ = {};
    storage_ = storage;
  }
  if (storage_ == Storage::Texture)
    uploadTexture(field);
  else
    uploadBuffer(field);
  dims_ = field.dims();
  masked_ = field.hasValidity();
  lastUploadMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void GpuField::uploadTexture(const VectorField& field) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
  const glm::ivec3 d = field.dims();
  if (d.x > maxSize || d.y > maxSize || d.z > maxSize)
    throw Error(concat("the field's upload: a ", d.x, "x", d.y, "x", d.z,
                       " field exceeds this GPU's 3D ", "texture limit of ", maxSize,
                       " per axis; lower field.resolution"));
  // RGB32F (texelFetch reads alpha 1: every point valid), or RGBA32F with the
  // validity mask in alpha when the field has one.
  const bool masked = field.hasValidity(), half = field.halfPrecision();
  if (!texture_ || dims_ != d || masked_ != masked || half_ != half) {
    texture_ = gl::createTexture(GL_TEXTURE_3D);
    glGetError();
    const GLenum format =
        half ? (masked ? GL_RGBA16F : GL_RGB16F) : (masked ? GL_RGBA32F : GL_RGB32F);
    glTextureStorage3D(texture_.id(), 1, format, d.x, d.y, d.z);
    if (glGetError() != GL_NO_ERROR) {
      texture_ = {};
      throw Error(concat("the field's upload: no GPU memory for a ", d.x, "x", d.y, "x", d.z,
                         " field (", double(d.x) * d.y * d.z * (masked ? 16.0 : 12.0),
                         " bytes); lower field.resolution"));
    }
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  half_ = half;
  if (half) {
    // The values are already 16-bit exact: sent as halves, half the bytes, kept exactly.
    const std::vector<std::uint16_t> packed = halfTexels(field);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glTextureSubImage3D(texture_.id(), 0, 0, 0, 0, d.x, d.y, d.z, masked ? GL_RGBA : GL_RGB,
                        GL_HALF_FLOAT, packed.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    return;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (!masked) {
    glTextureSubImage3D(texture_.id(), 0, 0, 0, 0, d.x, d.y, d.z, GL_RGB, GL_FLOAT,
                        field.values().data());
    return;
  }
  const std::vector<glm::vec4> padded = withValidity(field);
  glTextureSubImage3D(texture_.id(), 0, 0, 0, 0, d.x, d.y, d.z, GL_RGBA, GL_FLOAT, padded.data());
}

std::vector<glm::vec4> GpuField::withValidity(const VectorField& field) {
  const std::span<const glm::vec3> values = field.values();
  const std::span<const std::uint8_t> valid = field.validity();
  std::vector<glm::vec4> padded(values.size());
  forChunks(values.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      padded[i] = glm::vec4(values[i], valid.empty() || valid[i] ? 1.0f : 0.0f);
  });
  return padded;
}

std::vector<std::uint16_t> GpuField::halfTexels(const VectorField& field) {
  const std::span<const glm::vec3> values = field.values();
  const std::span<const std::uint8_t> valid = field.validity();
  const std::size_t channels = field.hasValidity() ? 4 : 3;
  std::vector<std::uint16_t> packed(values.size() * channels);
  const std::uint16_t one = glm::packHalf1x16(1.0f), zero = glm::packHalf1x16(0.0f);
  forChunks(values.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const glm::u16vec3 h = glm::packHalf(values[i]);
      for (std::size_t c = 0; c < 3; ++c)
        packed[i * channels + c] = h[int(c)];
      if (channels == 4) packed[i * 4 + 3] = valid[i] ? one : zero;
    }
  });
  return packed;
}

bool GpuField::fitsBuffer(const VectorField& field) {
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  return GLint64(field.values().size() * sizeof(glm::vec4)) <= maxBlock;
}

void GpuField::uploadBuffer(const VectorField& field) {
  const std::vector<glm::vec4> padded = withValidity(field);  // w: 1 valid, 0 not
  const GLsizeiptr bytes = GLsizeiptr(padded.size() * sizeof(glm::vec4));
  if (!buffer_ || dims_ != field.dims()) {
    buffer_ = gl::createBuffer();
    glGetError();
    glNamedBufferStorage(buffer_.id(), bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    if (glGetError() != GL_NO_ERROR) {
      buffer_ = {};
      const glm::ivec3 d = field.dims();
      throw Error(concat("the field's upload: no GPU memory for a ", d.x, "x", d.y, "x", d.z,
                         " field (", bytes, " bytes); lower field.resolution"));
    }
  }
  glNamedBufferSubData(buffer_.id(), 0, bytes, padded.data());
}

void GpuField::show(std::shared_ptr<const VectorField> field) {
  if (!field || field == holds_) return;
  upload(*field);
  holds_ = std::move(field);
}

void GpuField::bind(Slot slot) const {
  const bool current = slot == Slot::Current;
  if (storage_ == Storage::Texture)
    glBindTextureUnit(current ? 0 : 2, texture_.id());
  else
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, current ? 14 : 15, buffer_.id());
}

void TerrainTexture::upload(const HeightMap& terrain) {
  const glm::ivec2 d = terrain.dims();
  texture_ = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(texture_.id(), 1, GL_R32F, d.x, d.y);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture_.id(), 0, 0, 0, d.x, d.y, GL_RED, GL_FLOAT, terrain.heights().data());
}

void TerrainTexture::bind(int unit) const {
  glBindTextureUnit(GLuint(unit), texture_.id());
}

void GpuField::bindTexture(int unit) const {
  glBindTextureUnit(GLuint(unit), texture_.id());
}

}  // namespace sandstorm
