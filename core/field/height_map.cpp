#include "core/field/height_map.h"

#include <algorithm>

#include "core/util/error.h"

namespace sandstorm {

HeightMap::HeightMap(glm::vec2 min, glm::vec2 max, glm::ivec2 dims, std::vector<float> heights)
    : min_(min), max_(max), dims_(dims), heights_(std::move(heights)) {
  if (dims.x < 2 || dims.y < 2)
    throw Error(concat("HeightMap: ", dims.x, "x", dims.y, " grid; expected at least 2x2"));
  if (!(max.x > min.x) || !(max.y > min.y)) throw Error("HeightMap: empty extent");
  if (heights_.size() != std::size_t(dims.x) * std::size_t(dims.y))
    throw Error(
        concat("HeightMap: ", heights_.size(), " heights for a ", dims.x, "x", dims.y, " grid"));
  indexScale_ = glm::vec2(dims - 1) / (max - min);
}

HeightMap HeightMap::flat(float height, float halfSize) {
  return HeightMap({-halfSize, -halfSize}, {halfSize, halfSize}, {2, 2},
                   std::vector<float>(4, height));
}

bool HeightMap::isFlat() const {
  for (const float h : heights_)
    if (h != heights_.front()) return false;
  return true;
}

float HeightMap::heightAt(glm::vec2 p) const {
  const glm::vec2 u = glm::clamp((p - min_) * indexScale_, glm::vec2(0.0f), glm::vec2(dims_ - 1));
  const glm::ivec2 i0 = glm::min(glm::ivec2(glm::floor(u)), dims_ - 2);
  const glm::vec2 f = u - glm::vec2(i0);
  const float h00 = at(i0.x, i0.y), h10 = at(i0.x + 1, i0.y);
  const float h01 = at(i0.x, i0.y + 1), h11 = at(i0.x + 1, i0.y + 1);
  const float h0 = h00 + (h10 - h00) * f.x;
  const float h1 = h01 + (h11 - h01) * f.x;
  return h0 + (h1 - h0) * f.y;
}

glm::vec3 HeightMap::normalAt(glm::vec2 p) const {
  const glm::vec2 d = (max_ - min_) / glm::vec2(dims_ - 1);
  const float dx = heightAt(p + glm::vec2(d.x, 0)) - heightAt(p - glm::vec2(d.x, 0));
  const float dy = heightAt(p + glm::vec2(0, d.y)) - heightAt(p - glm::vec2(0, d.y));
  return glm::normalize(glm::vec3(-dx / (2 * d.x), -dy / (2 * d.y), 1.0f));
}

float HeightMap::minHeight() const {
  return *std::min_element(heights_.begin(), heights_.end());
}
float HeightMap::maxHeight() const {
  return *std::max_element(heights_.begin(), heights_.end());
}

}  // namespace sandstorm
