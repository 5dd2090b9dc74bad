// GpuField: a VectorField's grid on the GPU, in one of three storages, and
// TerrainTexture: a HeightMap as an R32F 2D texture. Shaders read both
// without the sampler's filter and interpolate themselves
// (shaders/particle_physics.glsl), so the GPU agrees with the CPU bit for bit.
//   Texture: an RGBA32F 3D texture read with texelFetch (thesis 5.2); the
//     transform-feedback backend's. Alpha is the validity mask
//     (VectorField::setValidity), 1 everywhere without one. Its layers are
//     written by a compute pass from the staging buffer (field_unpack.comp):
//     NVIDIA's driver unpacked an RGB32F texture from a buffer at 1.3-2.7
//     GB/s, the first frame's wait for a 512^3 file. A field rounded to half
//     precision (field.precision = "half") is RGB16F or RGBA16F, unpacked by
//     the driver: texelFetch returns the very values the CPU twin samples,
//     in half the memory.
//   Buffer: a shader storage buffer of vec4 (xyz, w: 1 valid, 0 not), x fastest; what
//     the compute backend prefers: on an H200 its eight loads a sample made
//     the update 12% (RK2) to 23% (RK4) faster than eight texelFetch
//     (docs/PERFORMANCE.md).
//   HalfBuffer: the same for a half-precision grid, four halves a point
//     (x, y, z, w: 1 valid, 0 not; the RGBA16F texel's bytes), read as a
//     uvec2 and unpacked (FIELD_BUFFER_HALF). A series' step goes to it with
//     a copy between buffers, where a 16-bit texture's upload converts.
//   A grid larger than the GPU's storage-buffer limit
//   (GL_MAX_SHADER_STORAGE_BLOCK_SIZE: 128 MiB on llvmpipe) is kept as a
//   texture instead; storage() says which. [gpu] field_storage = "texture"
//   makes every grid take that fallback (tests, comparisons).
#pragma once

#include <memory>
#include <vector>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "core/field/height_map.h"
#include "core/field/vector_field.h"

namespace sandstorm {

class GpuField {
 public:
  // Preferred: Texture or Buffer (a half-precision grid then takes HalfBuffer).
  enum class Storage { Texture, Buffer, HalfBuffer };
  // Where a field is bound: the current frame or a time-varying field's next.
  enum class Slot { Current, Next };

  explicit GpuField(Storage preferred) : preferred_(preferred), storage_(preferred) {}

  // Uploads; throws Error when the grid exceeds what this GPU holds
  // (GL_MAX_3D_TEXTURE_SIZE; memory). Re-uploading a field of the same
  // dimensions reuses the texture or buffer.
  void upload(const VectorField& field);
  // Uploads unless this already holds that very field.
  void show(std::shared_ptr<const VectorField> field);
  const std::shared_ptr<const VectorField>& holds() const { return holds_; }
  // How the field last uploaded is kept.
  Storage storage() const { return storage_; }
  // Texture: units 0 (current) and 2 (next); buffers: storage-buffer bindings
  // 14 and 15 (shaders/sim_block.glsl).
  void bind(Slot slot) const;
  // A texture-stored grid on any texture unit (the vorticity grids: units 5 and 6).
  void bindTexture(int unit) const;

  // An upload in parts (GridPrefetch), what upload() does in one go:
  // prepare() makes the texture or buffer ready for `field` (forgetting what
  // this held) and returns the bytes a z layer of its texels takes;
  // writeLayers() writes layers of them anywhere, from any thread (no GL),
  // over at most `threads` threads (0: the machine's cores);
  // copyLayers() copies layers from a buffer holding them, at `offset`;
  // hold() marks the field held once every layer is copied.
  std::size_t prepare(const VectorField& field);
  void writeLayers(const VectorField& field, int firstLayer, int layers, void* out,
                   unsigned threads = 0) const;
  void copyLayers(const gl::Buffer& staging, std::size_t offset, int firstLayer, int layers);
  void hold(std::shared_ptr<const VectorField> field) { holds_ = std::move(field); }

 private:
  static bool fitsBuffer(const VectorField& field);
  void allocateTexture(const VectorField& field);
  void allocateBuffer(const VectorField& field, std::size_t pointBytes);
  // How the grid's points are laid out for the GPU: float or half, RGB, or
  // RGBA with the validity mask in alpha (the buffers' points are FloatRgba
  // and HalfRgba).
  enum class Layout { FloatRgb, FloatRgba, HalfRgb, HalfRgba };
  static std::size_t texelBytes(Layout layout);
  std::size_t layerBytes() const {
    return std::size_t(dims_.x) * std::size_t(dims_.y) * texelBytes(layout_);
  }
  // The grid through staging buffers the GPU copies from (so the frame does
  // not wait for the driver to take a copy of hundreds of megabytes), a slab
  // of whole z layers at a time, each written over the cores through a
  // mapping and copied (copyLayers). Two slabs of about kSlabBytes: staging
  // takes tens of megabytes of host memory, not a second copy of the grid.
  void stageSlabs(const VectorField& field);
  static constexpr std::size_t kSlabBytes = std::size_t{32} << 20;
  // copyLayers into a float texture: field_unpack.comp over the staged
  // layers, as many a dispatch as one storage-buffer binding holds; false
  // where not one layer fits a binding (the driver's unpack then).
  bool unpackLayers(const gl::Buffer& staging, std::size_t offset, int firstLayer, int layers);

  std::unique_ptr<gl::Program> unpack_;  // field_unpack.comp, made at its first use

  Storage preferred_, storage_;
  gl::Texture texture_;
  gl::Buffer buffer_;
  std::shared_ptr<const VectorField> holds_;
  glm::ivec3 dims_{0};
  Layout layout_ = Layout::FloatRgba;
};

class TerrainTexture {
 public:
  void upload(const HeightMap& terrain);
  void bind(int unit) const;

 private:
  gl::Texture texture_;
};

}  // namespace sandstorm
