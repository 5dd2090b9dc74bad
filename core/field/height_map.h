// HeightMap: ground height z(x, y) on a regular grid, for the scene's terrain
// and for particle collisions. Heights live at grid points over `min..max` in
// x and y, stored x-fastest; lookups are bilinear and clamp to the edges, with
// exactly the operations of terrainHeight() in shaders/particle_physics.glsl.
// A flat ground is a 2x2 map of one height.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

class HeightMap {
 public:
  HeightMap() : HeightMap({-1e4f, -1e4f}, {1e4f, 1e4f}, {2, 2}, std::vector<float>(4, 0.0f)) {}
  // Throws Error for dims < 2, an empty extent or a height count that differs.
  HeightMap(glm::vec2 min, glm::vec2 max, glm::ivec2 dims, std::vector<float> heights);

  static HeightMap flat(float height, float halfSize = 1e4f);

  glm::vec2 min() const { return min_; }
  glm::vec2 max() const { return max_; }
  glm::ivec2 dims() const { return dims_; }
  const std::vector<float>& heights() const { return heights_; }
  float at(int i, int j) const { return heights_[std::size_t(i) + std::size_t(dims_.x) * j]; }
  glm::vec2 indexScale() const { return indexScale_; }

  // Every height the same (a plane: the scene draws it by compute).
  bool isFlat() const;
  float heightAt(glm::vec2 p) const;
  glm::vec3 normalAt(glm::vec2 p) const;  // for shading, by central differences
  float minHeight() const;
  float maxHeight() const;

 private:
  glm::vec2 min_, max_;
  glm::ivec2 dims_;
  glm::vec2 indexScale_;
  std::vector<float> heights_;
};

}  // namespace sandstorm
