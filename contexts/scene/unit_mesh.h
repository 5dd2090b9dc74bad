// UnitMesh: a unit sphere (radius 0.5) or cylinder (diameter 1, height 1,
// vertical axis), centred on the origin, with smooth normals (position,
// normal per vertex), for the obstacles the scene draws stretched by a model
// matrix. Draw with mesh.vert/.frag, like UnitCube.
#pragma once

#include <cstddef>

#include "contexts/gl/objects.h"

namespace sandstorm {

class UnitMesh {
 public:
  static UnitMesh sphere(int segments = 32);
  static UnitMesh cylinder(int segments = 48);
  void draw() const;  // binds its vertex array and draws its triangles

 private:
  UnitMesh() = default;
  // Vertices as (position, normal) pairs of vec3.
  void upload(const float* vertices, std::size_t count);
  gl::Buffer vertices_;
  gl::VertexArray vao_;
  int count_ = 0;
};

}  // namespace sandstorm
