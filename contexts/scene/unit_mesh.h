// UnitMesh: a unit sphere (radius 0.5) or cylinder (diameter 1, height 1,
// vertical axis), centred on the origin, with smooth normals (position,
// normal per vertex), for the obstacles the scene draws stretched by a model
// matrix; or any triangles given (the helicopter's parts). Draw with
// mesh.vert/.frag, like UnitCube.
#pragma once

#include <cstddef>

#include <span>

#include "contexts/gl/objects.h"
#include "core/props/helicopter_model.h"

namespace sandstorm {

class UnitMesh {
 public:
  static UnitMesh sphere(int segments = 32);
  static UnitMesh cylinder(int segments = 48);
  // Any triangles (a prop's part, core/props/), as they are.
  static UnitMesh triangles(std::span<const ModelVertex> vertices);
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
