#include "core/tracking/wand_ray.h"

#include <algorithm>
#include <cmath>

namespace sandstorm {

std::optional<WallHit> hitWall(const Ray& ray, const WallCorners& wall) {
  const glm::vec3 right = wall.lowerRight - wall.lowerLeft;
  const glm::vec3 up = wall.upperLeft - wall.lowerLeft;
  const glm::vec3 normal = glm::cross(right, up);
  const float facing = glm::dot(ray.direction, normal);
  if (std::abs(facing) < 1e-9f) return std::nullopt;  // parallel to the wall
  const float t = glm::dot(wall.lowerLeft - ray.origin, normal) / facing;
  if (!(t >= 0.0f)) return std::nullopt;
  const glm::vec3 p = ray.at(t) - wall.lowerLeft;
  const glm::vec2 uv(glm::dot(p, right) / glm::dot(right, right),
                     glm::dot(p, up) / glm::dot(up, up));
  if (uv.x < 0.0f || uv.x > 1.0f || uv.y < 0.0f || uv.y > 1.0f) return std::nullopt;
  return WallHit{t, uv};
}

std::optional<float> hitSphere(const Ray& ray, const glm::vec3& centre, float radius) {
  const glm::vec3 oc = ray.origin - centre;
  const float b = glm::dot(oc, ray.direction);
  const float c = glm::dot(oc, oc) - radius * radius;
  if (c <= 0.0f) return 0.0f;  // inside
  const float disc = b * b - c;
  if (disc < 0.0f) return std::nullopt;
  const float t = -b - std::sqrt(disc);
  if (t < 0.0f) return std::nullopt;
  return t;
}

std::optional<float> hitGround(const Ray& ray, const Navigation& navigation,
                               const HeightMap& ground, float maxT) {
  // The navigation is a similarity, so the ray stays a ray in the world.
  const glm::vec3 o = navigation.roomToWorld(ray.origin);
  const glm::vec3 d = navigation.roomToWorld(ray.origin + ray.direction) - o;
  const auto above = [&](float t) {
    const glm::vec3 p = o + t * d;
    return p.z - ground.heightAt({p.x, p.y});
  };
  if (above(0.0f) < 0.0f) return std::nullopt;  // starts under the ground
  // March in steps no coarser than the terrain's grid, then bisect the crossing.
  const glm::vec2 cell = (ground.max() - ground.min()) / glm::vec2(ground.dims() - 1);
  const float worldStep = std::max(0.25f * std::min(cell.x, cell.y), 1e-3f);
  const float roomStep =
      std::clamp(worldStep * navigation.scale, 0.005f, std::max(maxT / 64.0f, 0.005f));
  float a = 0.0f;
  for (float b = roomStep; a < maxT; a = b, b += roomStep) {
    b = std::min(b, maxT);
    if (above(b) > 0.0f) continue;
    for (int i = 0; i < 40; ++i) {
      const float m = 0.5f * (a + b);
      (above(m) > 0.0f ? a : b) = m;
    }
    return b;
  }
  return std::nullopt;
}

}  // namespace sandstorm
