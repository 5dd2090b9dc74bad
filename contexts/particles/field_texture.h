// FieldTexture: a VectorField on the GPU as an RGB32F 3D texture (thesis 5.2),
// and TerrainTexture: a HeightMap as an R32F 2D texture. Shaders read both with
// texelFetch and interpolate themselves (shaders/particle_physics.glsl).
#pragma once

#include <memory>

#include "contexts/gl/objects.h"
#include "core/field/height_map.h"
#include "core/field/vector_field.h"

namespace sandstorm {

class FieldTexture {
 public:
  // Uploads; throws Error when the grid exceeds GL_MAX_3D_TEXTURE_SIZE.
  // Re-uploading a field of the same dimensions reuses the texture.
  void upload(const VectorField& field);
  // Uploads unless this texture already holds that very field.
  void show(std::shared_ptr<const VectorField> field);
  const std::shared_ptr<const VectorField>& holds() const { return holds_; }
  void bind(int unit) const;
  double lastUploadMs() const { return lastUploadMs_; }

 private:
  gl::Texture texture_;
  std::shared_ptr<const VectorField> holds_;
  glm::ivec3 dims_{0};
  double lastUploadMs_ = 0.0;
};

class TerrainTexture {
 public:
  void upload(const HeightMap& terrain);
  void bind(int unit) const;

 private:
  gl::Texture texture_;
};

}  // namespace sandstorm
