#include "contexts/particles/gpu_field.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string_view>
#include <thread>
#include <vector>

#include "core/util/error.h"
#include "core/util/half_arrays.h"
#include "core/util/parallel_for.h"

namespace sandstorm {

// HalfRgba points are written as one 64-bit word: x in its low 16 bits,
// first in memory, as the GPU reads them.
static_assert(std::endian::native == std::endian::little);

void GpuField::upload(const VectorField& field) {
  prepare(field);
  stageSlabs(field);
}

std::size_t GpuField::prepare(const VectorField& field) {
  holds_ = nullptr;
  const bool masked = field.hasValidity(), half = field.halfPrecision();
  const Storage storage = preferred_ == Storage::Texture || !fitsBuffer(field) ? Storage::Texture
                          : half                                               ? Storage::HalfBuffer
                                                                               : Storage::Buffer;
  if (storage != storage_) {
    texture_ = {};
    buffer_ = {};
    storage_ = storage;
  }
  // A buffer's point carries the mask (w: 1 valid, 0 not) whether or not there is one.
  const Layout layout = storage_ == Storage::Buffer       ? Layout::FloatRgba
                        : storage_ == Storage::HalfBuffer ? Layout::HalfRgba
                        : half ? (masked ? Layout::HalfRgba : Layout::HalfRgb)
                               : (masked ? Layout::FloatRgba : Layout::FloatRgb);
  const bool same = dims_ == field.dims() && layout_ == layout;
  if (storage_ == Storage::Texture && !(texture_ && same)) allocateTexture(field);
  if (storage_ != Storage::Texture && !(buffer_ && same)) allocateBuffer(field, texelBytes(layout));
  dims_ = field.dims();
  layout_ = layout;
  return layerBytes();
}

void GpuField::allocateTexture(const VectorField& field) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
  const glm::ivec3 d = field.dims();
  if (d.x > maxSize || d.y > maxSize || d.z > maxSize)
    throw Error(concat("the field's upload: a ", d.x, "x", d.y, "x", d.z,
                       " field exceeds this GPU's 3D ", "texture limit of ", maxSize,
                       " per axis; lower field.resolution"));
  // Floats: RGBA32F, the validity mask in alpha (1 without one), the format
  // a compute pass can write (field_unpack.comp). Halves: RGB16F (texelFetch
  // reads alpha 1: every point valid), or RGBA16F with the mask in alpha.
  const bool masked = field.hasValidity(), half = field.halfPrecision();
  texture_ = gl::createTexture(GL_TEXTURE_3D);
  glGetError();
  const GLenum format = half ? (masked ? GL_RGBA16F : GL_RGB16F) : GL_RGBA32F;
  glTextureStorage3D(texture_.id(), 1, format, d.x, d.y, d.z);
  if (glGetError() != GL_NO_ERROR) {
    texture_ = {};
    dims_ = glm::ivec3(0);
    throw Error(concat("the field's upload: no GPU memory for a ", d.x, "x", d.y, "x", d.z,
                       " field (", double(d.x) * d.y * d.z * (half ? (masked ? 8.0 : 6.0) : 16.0),
                       " bytes); lower field.resolution"));
  }
  glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void GpuField::allocateBuffer(const VectorField& field, std::size_t pointBytes) {
  const GLsizeiptr bytes = GLsizeiptr(field.pointCount() * pointBytes);
  buffer_ = gl::createBuffer();
  glGetError();
  glNamedBufferStorage(buffer_.id(), bytes, nullptr, 0);
  if (glGetError() != GL_NO_ERROR) {
    buffer_ = {};
    dims_ = glm::ivec3(0);
    const glm::ivec3 d = field.dims();
    throw Error(concat("the field's upload: no GPU memory for a ", d.x, "x", d.y, "x", d.z,
                       " field (", bytes, " bytes); lower field.resolution"));
  }
}

void GpuField::copyLayers(const gl::Buffer& staging, std::size_t offset, int firstLayer,
                          int layers) {
  if (storage_ != Storage::Texture) {
    glCopyNamedBufferSubData(staging.id(), buffer_.id(), GLintptr(offset),
                             GLintptr(std::size_t(firstLayer) * layerBytes()),
                             GLsizeiptr(std::size_t(layers) * layerBytes()));
    return;
  }
  const bool masked = layout_ == Layout::FloatRgba || layout_ == Layout::HalfRgba;
  const bool half = layout_ == Layout::HalfRgb || layout_ == Layout::HalfRgba;
  if (!half && unpackLayers(staging, offset, firstLayer, layers)) return;
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, staging.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, half ? 2 : 4);
  glTextureSubImage3D(texture_.id(), 0, 0, 0, firstLayer, dims_.x, dims_.y, layers,
                      masked ? GL_RGBA : GL_RGB, half ? GL_HALF_FLOAT : GL_FLOAT,
                      reinterpret_cast<const void*>(offset));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

bool GpuField::unpackLayers(const gl::Buffer& staging, std::size_t offset, int firstLayer,
                            int layers) {
  GLint64 maxBlock = 0;
  GLint align = 1;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
  const std::size_t layer = layerBytes(), alignment = std::size_t(std::max(align, 1));
  // A binding starts at an aligned offset, up to alignment - 1 bytes before the layers.
  const std::size_t room = std::size_t(std::max<GLint64>(maxBlock, 0));
  if (room < alignment || (room - alignment) / layer < 1) return false;
  const int perDispatch =
      int(std::min<std::size_t>((room - alignment) / layer, std::size_t(layers)));
  if (!unpack_)
    unpack_ = std::make_unique<gl::Program>(std::vector<std::string>{"field_unpack.comp"});
  // The binding used is given back as it was: other passes bind theirs once.
  GLint previous = 0;
  GLint64 previousStart = 0, previousSize = 0;
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 0, &previous);
  glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, 0, &previousStart);
  glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, 0, &previousSize);
  const GLuint program = unpack_->id();
  unpack_->use();
  glProgramUniform2ui(program, 0, GLuint(dims_.x), GLuint(dims_.y));
  glProgramUniform1ui(program, 3, layout_ == Layout::FloatRgba ? 4u : 3u);
  glBindImageTexture(0, texture_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  for (int z = 0; z < layers; z += perDispatch) {
    const int n = std::min(perDispatch, layers - z);
    const std::size_t at = offset + std::size_t(z) * layer;
    const std::size_t base = at / alignment * alignment;
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, staging.id(), GLintptr(base),
                      GLsizeiptr(at - base + std::size_t(n) * layer));
    const std::size_t points = std::size_t(n) * std::size_t(dims_.x) * std::size_t(dims_.y);
    glProgramUniform1ui(program, 1, GLuint(firstLayer + z));
    glProgramUniform1ui(program, 2, GLuint(points));
    glProgramUniform1ui(program, 4, GLuint((at - base) / sizeof(float)));
    // Enough workgroups to fill any GPU; each invocation strides over the rest.
    glDispatchCompute(GLuint(std::clamp<std::size_t>((points + 255) / 256, 1, 8192)), 1, 1);
  }
  // Sampled next (here, or in a context that waits for this one's fence).
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  if (previous != 0 && previousSize > 0)
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, GLuint(previous), GLintptr(previousStart),
                      GLsizeiptr(previousSize));
  else
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, GLuint(previous));
  return true;
}

std::size_t GpuField::texelBytes(Layout layout) {
  switch (layout) {
    case Layout::FloatRgb:
      return 12;
    case Layout::FloatRgba:
      return 16;
    case Layout::HalfRgb:
      return 6;
    case Layout::HalfRgba:
      return 8;
  }
  return 16;
}

void GpuField::writeLayers(const VectorField& field, int firstLayer, int layers, void* out,
                           unsigned threads) const {
  const std::size_t layerPoints = std::size_t(dims_.x) * std::size_t(dims_.y);
  const std::size_t first = std::size_t(firstLayer) * layerPoints;
  const std::size_t count = std::size_t(layers) * layerPoints;
  const Layout layout = layout_;
  const std::span<const glm::vec3> values = field.values().subspan(first, count);
  const std::span<const std::uint8_t> valid =
      field.hasValidity() ? field.validity().subspan(first, count) : field.validity();
  const auto isValid = [&](std::size_t i) { return valid.empty() || valid[i] != 0; };
  // The grid's values are halves already (VectorField::roundToHalf): their
  // bits, eight or four at a time (core/util/half_arrays.h), a point's four
  // stored at once (the mapping may be write-combined memory).
  const float* components = &values.data()->x;
  const auto write = [&](std::size_t begin, std::size_t end) {
    switch (layout) {
      case Layout::FloatRgb:
        std::memcpy(static_cast<glm::vec3*>(out) + begin, values.data() + begin,
                    (end - begin) * sizeof(glm::vec3));
        break;
      case Layout::FloatRgba:  // w: 1 valid, 0 not
        for (std::size_t i = begin; i < end; ++i)
          static_cast<glm::vec4*>(out)[i] = glm::vec4(values[i], isValid(i) ? 1.0f : 0.0f);
        break;
      case Layout::HalfRgb:
        halvesToBits(components + 3 * begin, 3 * (end - begin),
                     static_cast<std::uint16_t*>(out) + 3 * begin);
        break;
      case Layout::HalfRgba:  // w: 1 valid, 0 not
        packHalfPoints(components + 3 * begin, valid.empty() ? nullptr : valid.data() + begin,
                       end - begin, static_cast<std::uint64_t*>(out) + begin);
        break;
    }
  };
  forChunks(count, write,
            threads == 0 ? std::size_t{1} << 16
                         : std::max<std::size_t>(1, (count + threads - 1) / threads));
}

void GpuField::stageSlabs(const VectorField& field) {
  const glm::ivec3 d = dims_;
  const int slabLayers =
      int(std::clamp<std::size_t>(kSlabBytes / layerBytes(), 1, std::size_t(d.z)));
  const GLsizeiptr slabBytes = GLsizeiptr(std::size_t(slabLayers) * layerBytes());
  // Two slabs: the cores fill one while the GPU copies the other. Mapping a
  // slab again waits for the GPU's copy out of it (no unsynchronized map);
  // invalidated, its old contents need not be kept.
  std::array<gl::Buffer, 2> ring;
  for (gl::Buffer& b : ring) {
    b = gl::createBuffer();
    glGetError();
    glNamedBufferStorage(b.id(), slabBytes, nullptr, GL_MAP_WRITE_BIT);
    if (glGetError() != GL_NO_ERROR)
      throw Error(concat("the field's upload: no memory to stage a ", d.x, "x", d.y, "x", d.z,
                         " field (slabs of ", slabBytes, " bytes); lower field.resolution"));
    if (slabLayers >= d.z) break;  // one slab holds the grid
  }
  for (int z = 0, slab = 0; z < d.z; z += slabLayers, slab ^= 1) {
    const int layers = std::min(slabLayers, d.z - z);
    const gl::Buffer& staging = ring[std::size_t(slab)];
    const GLsizeiptr bytes = GLsizeiptr(std::size_t(layers) * layerBytes());
    void* out = glMapNamedBufferRange(staging.id(), 0, bytes,
                                      GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
    if (!out)
      throw Error(concat("the field's upload: no memory to stage a ", d.x, "x", d.y, "x", d.z,
                         " field (slabs of ", slabBytes, " bytes); lower field.resolution"));
    writeLayers(field, z, layers, out);
    glUnmapNamedBuffer(staging.id());
    copyLayers(staging, 0, z, layers);
  }
}

bool GpuField::fitsBuffer(const VectorField& field) {
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  const std::size_t pointBytes =
      texelBytes(field.halfPrecision() ? Layout::HalfRgba : Layout::FloatRgba);
  return GLint64(field.values().size() * pointBytes) <= maxBlock;
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
