// GpuField's choice of storage: the compute backend's storage buffer where the
// grid fits this GPU's storage-buffer limit, a texture where it does not or
// [gpu] field_storage = "texture" says; particles moved through a grid kept
// either way match the CPU reference (particle_geo_update_test.cpp).
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cmath>

#include "contexts/particles/gpu_field.h"
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

}  // namespace
}  // namespace sandstorm
