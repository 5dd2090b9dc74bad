#include "contexts/particles/field_texture.h"

#include <epoxy/gl.h>

#include <chrono>
#include <cstdlib>
#include <string_view>

#include "core/util/error.h"

namespace sandstorm {

void FieldTexture::upload(const VectorField& field) {
  const auto start = std::chrono::steady_clock::now();
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
  const glm::ivec3 d = field.dims();
  if (d.x > maxSize || d.y > maxSize || d.z > maxSize)
    throw Error(concat("FieldTexture: a ", d.x, "x", d.y, "x", d.z, " field exceeds this GPU's 3D ",
                       "texture limit of ", maxSize, " per axis; resample it to a coarser grid"));
  if (!texture_ || dims_ != d) {
    texture_ = gl::createTexture(GL_TEXTURE_3D);
    // RGB32F; SANDSTORM_FIELD_FORMAT=rgba32f stores the same values padded to
    // four (measured on an H200: no faster for the compute update, slower for
    // transform feedback; docs/PERFORMANCE.md).
    const char* format = std::getenv("SANDSTORM_FIELD_FORMAT");
    const GLenum internal =
        format && std::string_view(format) == "rgba32f" ? GL_RGBA32F : GL_RGB32F;
    glTextureStorage3D(texture_.id(), 1, internal, d.x, d.y, d.z);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    dims_ = d;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage3D(texture_.id(), 0, 0, 0, 0, d.x, d.y, d.z, GL_RGB, GL_FLOAT,
                      field.values().data());
  lastUploadMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void FieldTexture::show(std::shared_ptr<const VectorField> field) {
  if (!field || field == holds_) return;
  upload(*field);
  holds_ = std::move(field);
}

void FieldTexture::bind(int unit) const {
  glBindTextureUnit(GLuint(unit), texture_.id());
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

}  // namespace sandstorm
