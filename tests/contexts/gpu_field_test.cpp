// GpuField's choice of storage: the compute backend's storage buffer where the
// grid fits this GPU's storage-buffer limit, a texture where it does not or
// [gpu] field_storage = "texture" says; particles moved through a grid kept
// either way match the CPU reference (particle_geo_update_test.cpp).
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "contexts/particles/gpu_field.h"
#include "core/util/half_float.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class GpuFieldTest : public GlTest {};

VectorField grid(glm::ivec3 dims) {
  return VectorField(Box{{0, 0, 0}, {1, 1, 1}}, dims);
}

TEST_F(GpuFieldTest, APreferredBufferHoldsAGridThatFits) {
  GpuField field(GpuField::Storage::Buffer);
  field.upload(grid({8, 8, 8}));
  EXPECT_EQ(field.storage(), GpuField::Storage::Buffer);
  GpuField texture(GpuField::Storage::Texture);
  texture.upload(grid({8, 8, 8}));
  EXPECT_EQ(texture.storage(), GpuField::Storage::Texture);
}

TEST_F(GpuFieldTest, AGridBeyondTheStorageBufferLimitIsKeptAsATexture) {
  GLint64 limit = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
  const int side = int(std::cbrt(double(limit) / 16.0)) + 1;  // 16 bytes a point in a buffer
  if (std::int64_t(side) * side * side * 12 > (std::int64_t(1) << 30))
    GTEST_SKIP() << "this GPU's storage-buffer limit (" << limit << " bytes) is too large to pass";
  GpuField field(GpuField::Storage::Buffer);
  field.upload(grid({side, side, side}));
  EXPECT_EQ(field.storage(), GpuField::Storage::Texture);
  field.upload(grid({8, 8, 8}));  // and back when the next grid fits
  EXPECT_EQ(field.storage(), GpuField::Storage::Buffer);
}

VectorField halfGrid(bool masked) {
  VectorField f = grid({6, 5, 4});
  for (std::size_t i = 0; i < f.pointCount(); ++i)
    f.values()[i] = glm::vec3(0.013f * float(i), -1.7f + float(i % 5), 1000.0f / float(i + 3));
  f.values()[3] = glm::vec3(-0.0f, 3e-6f, -6.0e-8f);  // zero and subnormal halves
  if (masked) {
    std::vector<std::uint8_t> valid(f.pointCount(), 1);
    valid[7] = 0;
    f.setValidity(valid);
  }
  f.roundToHalf();
  return f;
}

TEST_F(GpuFieldTest, AHalfPrecisionGridIsASixteenBitTextureHoldingItsValuesExactly) {
  for (const bool masked : {false, true}) {
    SCOPED_TRACE(masked ? "masked" : "unmasked");
    const VectorField f = halfGrid(masked);
    GpuField field(GpuField::Storage::Texture);
    field.upload(f);
    ASSERT_EQ(field.storage(), GpuField::Storage::Texture);
    GLint texture = 0;
    field.bindTexture(3);
    glActiveTexture(GL_TEXTURE3);
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &texture);
    GLint format = 0;
    glGetTextureLevelParameteriv(GLuint(texture), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    EXPECT_EQ(format, masked ? GL_RGBA16F : GL_RGB16F);
    std::vector<glm::vec4> texels(f.pointCount());
    glGetTextureImage(GLuint(texture), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * 16),
                      texels.data());
    for (std::size_t i = 0; i < f.pointCount(); ++i) {
      ASSERT_EQ(glm::vec3(texels[i]), f.values()[i]) << "point " << i;
      EXPECT_EQ(texels[i].w, masked && i == 7 ? 0.0f : 1.0f);
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
}

// A float grid's texture: RGBA32F, its layers written by a compute pass
// (field_unpack.comp) from the staged points: every component's bits as the
// CPU holds them (-0, subnormals, the largest float), alpha the mask.
TEST_F(GpuFieldTest, AFloatGridInATextureHoldsItsValuesBitForBit) {
  for (const bool masked : {false, true}) {
    SCOPED_TRACE(masked ? "masked" : "unmasked");
    VectorField f = grid({7, 5, 6});
    for (std::size_t i = 0; i < f.pointCount(); ++i)
      f.values()[i] = glm::vec3(0.013f * float(i), -1.7f + float(i % 5), 1000.0f / float(i + 3));
    f.values()[3] = glm::vec3(-0.0f, 1e-40f, std::numeric_limits<float>::max());
    if (masked) {
      std::vector<std::uint8_t> valid(f.pointCount(), 1);
      valid[7] = 0;
      f.setValidity(valid);
    }
    GpuField field(GpuField::Storage::Texture);
    field.upload(f);
    ASSERT_EQ(field.storage(), GpuField::Storage::Texture);
    field.bindTexture(3);
    glActiveTexture(GL_TEXTURE3);
    GLint texture = 0, format = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &texture);
    glGetTextureLevelParameteriv(GLuint(texture), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    EXPECT_EQ(format, GL_RGBA32F);
    std::vector<glm::vec4> texels(f.pointCount());
    glGetTextureImage(GLuint(texture), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * 16),
                      texels.data());
    for (std::size_t i = 0; i < f.pointCount(); ++i) {
      ASSERT_EQ(std::memcmp(&texels[i], &f.values()[i], sizeof(glm::vec3)), 0) << "point " << i;
      EXPECT_EQ(texels[i].w, masked && i == 7 ? 0.0f : 1.0f);
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
}

// Layers staged anywhere in a buffer (GridPrefetch stages a whole step, at an
// offset no storage-buffer binding may start at) and more of them than one
// binding holds (GL_MAX_SHADER_STORAGE_BLOCK_SIZE: 128 MiB on llvmpipe): the
// copy goes in parts, each from an aligned start, and lands where it should;
// the layers before it keep theirs, and the storage binding it borrowed is
// given back.
TEST_F(GpuFieldTest, LayersCopiedFromAnyOffsetInPartsLandInPlace) {
  GLint64 limit = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
  const glm::ivec3 dims(128, 128, 0);
  const std::size_t layerBytes = std::size_t(dims.x) * dims.y * 12;
  const int layers = int(std::size_t(limit) / layerBytes) + 8;  // past one binding
  if (std::size_t(layers) * layerBytes > (std::size_t{1} << 30))
    GTEST_SKIP() << "this GPU's storage-buffer limit (" << limit << " bytes) is too large to pass";
  VectorField f = grid({dims.x, dims.y, layers + 1});
  for (std::size_t i = 0; i < f.pointCount(); ++i)
    f.values()[i] = glm::vec3(float(i), -float(i % 1001), 0.5f * float(i % 7));
  GpuField field(GpuField::Storage::Texture);
  ASSERT_EQ(field.prepare(f), layerBytes);
  const std::size_t pad = 12;  // a point: aligned to no binding's start
  gl::Buffer staging = gl::createBuffer();
  glNamedBufferStorage(staging.id(), GLsizeiptr(pad + std::size_t(layers) * layerBytes), nullptr,
                       GL_MAP_WRITE_BIT);
  auto* out = static_cast<std::uint8_t*>(glMapNamedBufferRange(
      staging.id(), 0, GLsizeiptr(pad + std::size_t(layers) * layerBytes), GL_MAP_WRITE_BIT));
  ASSERT_NE(out, nullptr);
  field.writeLayers(f, 1, layers, out + pad);
  glUnmapNamedBuffer(staging.id());
  gl::Buffer marker = gl::createBuffer();
  glNamedBufferStorage(marker.id(), 64, nullptr, 0);
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, marker.id(), 0, 32);
  field.copyLayers(staging, pad, 1, layers);  // layer 0 never written: zeros
  GLint bound = 0;
  GLint64 size = 0;
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 0, &bound);
  glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, 0, &size);
  EXPECT_EQ(GLuint(bound), marker.id());
  EXPECT_EQ(size, 32);
  field.bindTexture(3);
  glActiveTexture(GL_TEXTURE3);
  GLint texture = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_3D, &texture);
  const std::size_t perLayer = std::size_t(dims.x) * dims.y;
  // The first layers, those on either side of where one binding ends, the last.
  GLint align = 1;
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
  const int partLayers = int((std::size_t(limit) - std::size_t(align)) / layerBytes);
  for (const int z :
       {0, 1, 2, partLayers - 1, partLayers, partLayers + 1, partLayers + 2, layers}) {
    SCOPED_TRACE(testing::Message() << "layer " << z);
    std::vector<glm::vec4> texels(perLayer);
    glGetTextureSubImage(GLuint(texture), 0, 0, 0, z, dims.x, dims.y, 1, GL_RGBA, GL_FLOAT,
                         GLsizei(texels.size() * 16), texels.data());
    for (std::size_t i = 0; i < perLayer; ++i) {
      const glm::vec3 expected =
          z == 0 ? glm::vec3(0.0f) : f.values()[std::size_t(z) * perLayer + i];
      ASSERT_EQ(glm::vec3(texels[i]), expected) << "point " << i;
    }
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// The compute backend's half grid: a storage buffer of four halves a point
// (x, y, z, then 1 valid or 0 not), each the bits of the CPU's value.
TEST_F(GpuFieldTest, AHalfPrecisionGridInABufferHoldsFourHalvesAPoint) {
  for (const bool masked : {false, true}) {
    SCOPED_TRACE(masked ? "masked" : "unmasked");
    const VectorField f = halfGrid(masked);
    GpuField field(GpuField::Storage::Buffer);
    field.upload(f);
    ASSERT_EQ(field.storage(), GpuField::Storage::HalfBuffer);
    field.bind(GpuField::Slot::Next);
    GLint buffer = 0;
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 15, &buffer);
    GLint64 size = 0;
    glGetNamedBufferParameteri64v(GLuint(buffer), GL_BUFFER_SIZE, &size);
    ASSERT_EQ(size, GLint64(f.pointCount() * 8));
    std::vector<std::uint16_t> halves(f.pointCount() * 4);
    glGetNamedBufferSubData(GLuint(buffer), 0, GLsizeiptr(size), halves.data());
    for (std::size_t i = 0; i < f.pointCount(); ++i) {
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(halfToFloat(halves[i * 4 + std::size_t(c)]), f.values()[i][c])
            << "point " << i << ", component " << c;
      EXPECT_EQ(halfToFloat(halves[i * 4 + 3]), masked && i == 7 ? 0.0f : 1.0f);
    }
    EXPECT_TRUE(std::signbit(halfToFloat(halves[3 * 4])));  // -0 stays -0
    // Floats again: a buffer of vec4.
    field.upload(grid({6, 5, 4}));
    EXPECT_EQ(field.storage(), GpuField::Storage::Buffer);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
}

}  // namespace
}  // namespace sandstorm
