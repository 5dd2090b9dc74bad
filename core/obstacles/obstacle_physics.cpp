#include "core/obstacles/obstacle_physics.h"

#include <algorithm>
#include <cmath>

namespace sandstorm {
namespace {

float dot3(const glm::vec3& a, const glm::vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

float sign1(float x) {
  return x < 0.0f ? -1.0f : 1.0f;
}

ObstacleSurface sphereSurface(const Obstacle& o, const glm::vec3& x) {
  const glm::vec3 d = x - o.position;
  const float r = std::sqrt(dot3(d, d));
  ObstacleSurface s;
  s.distance = r - o.radius;
  if (r > 0.0f) s.normal = d / r;
  return s;
}

ObstacleSurface boxSurface(const Obstacle& o, const glm::vec3& x) {
  const glm::vec3 d = x - o.position;
  const glm::vec3 h = 0.5f * o.size;
  const glm::vec3 q = glm::abs(d) - h;
  ObstacleSurface s;
  if (q.x > 0.0f || q.y > 0.0f || q.z > 0.0f) {
    const glm::vec3 m = glm::max(q, glm::vec3(0.0f));
    const float length = std::sqrt(dot3(m, m));
    s.distance = length;
    s.normal = glm::vec3(sign1(d.x), sign1(d.y), sign1(d.z)) * (m / length);
    return s;
  }
  // Inside: the nearest face.
  int axis = 0;
  if (q.y > q[axis]) axis = 1;
  if (q.z > q[axis]) axis = 2;
  s.distance = q[axis];
  s.normal = glm::vec3(0.0f);
  s.normal[axis] = sign1(d[axis]);
  return s;
}

ObstacleSurface cylinderSurface(const Obstacle& o, const glm::vec3& x) {
  const glm::vec3 d = x - o.position;
  const float rho = std::sqrt(d.x * d.x + d.y * d.y);
  const glm::vec3 radial = rho > 0.0f ? glm::vec3(d.x / rho, d.y / rho, 0.0f) : glm::vec3(1, 0, 0);
  const float qr = rho - o.radius;
  const float qz = std::abs(d.z) - 0.5f * o.height;
  const glm::vec3 up(0.0f, 0.0f, sign1(d.z));
  ObstacleSurface s;
  if (qr > 0.0f || qz > 0.0f) {
    const float mr = std::max(qr, 0.0f), mz = std::max(qz, 0.0f);
    const float length = std::sqrt(mr * mr + mz * mz);
    s.distance = length;
    s.normal = (mr / length) * radial + (mz / length) * up;
    return s;
  }
  s.distance = std::max(qr, qz);
  s.normal = qr > qz ? radial : up;
  return s;
}

// A box's or cylinder's boundary layer: its smallest half-extent.
float layerThickness(const Obstacle& o) {
  if (o.shape == ObstacleShape::Box) return 0.5f * std::min(std::min(o.size.x, o.size.y), o.size.z);
  return std::min(o.radius, 0.5f * o.height);
}

// Whether x is certainly at least `layer` from a box's or cylinder's surface
// (outside), from its coordinates alone: most particles are, and this spares
// them the distance's square root and divisions. Conservative, so skipping
// changes nothing (the layer's weight is 0 there).
bool beyondLayer(const Obstacle& o, const glm::vec3& x, float layer) {
  const glm::vec3 d = glm::abs(x - o.position);
  if (o.shape == ObstacleShape::Box) {
    const glm::vec3 h = 0.5f * o.size;
    return d.x - h.x >= layer || d.y - h.y >= layer || d.z - h.z >= layer;
  }
  const float reach = o.radius + layer;
  return d.z - 0.5f * o.height >= layer || d.x * d.x + d.y * d.y >= reach * reach;
}

// Whether x is certainly outside the obstacle (not inside), cheaply.
bool clearOf(const Obstacle& o, const glm::vec3& x) {
  const glm::vec3 d = x - o.position;
  if (o.shape == ObstacleShape::Box) {
    const glm::vec3 q = glm::abs(d) - 0.5f * o.size;
    return q.x >= 0.0f || q.y >= 0.0f || q.z >= 0.0f;
  }
  const float r = 1.001f * o.radius;
  if (o.shape == ObstacleShape::Sphere) return dot3(d, d) >= r * r;
  return std::abs(d.z) - 0.5f * o.height >= 0.0f || d.x * d.x + d.y * d.y >= r * r;
}

// The height at which x's column leaves the obstacle upwards.
float topAbove(const Obstacle& o, const glm::vec3& x) {
  if (o.shape == ObstacleShape::Box) return o.position.z + 0.5f * o.size.z;
  if (o.shape == ObstacleShape::Cylinder) return o.position.z + 0.5f * o.height;
  const float dx = x.x - o.position.x, dy = x.y - o.position.y;
  const float across = std::max(o.radius * o.radius - (dx * dx + dy * dy), 0.0f);
  return o.position.z + std::sqrt(across);
}

}  // namespace

ObstacleSurface obstacleSurface(const Obstacle& o, const glm::vec3& x) {
  switch (o.shape) {
    case ObstacleShape::Sphere:
      return sphereSurface(o, x);
    case ObstacleShape::Box:
      return boxSurface(o, x);
    case ObstacleShape::Cylinder:
      return cylinderSurface(o, x);
  }
  return {};
}

glm::vec3 flowAroundObstacles(const glm::vec3& f, const glm::vec3& x,
                              std::span<const Obstacle> obstacles, bool velocityField) {
  glm::vec3 out = f;
  for (const Obstacle& o : obstacles) {
    if (!o.flow) continue;
    const glm::vec3 u = velocityField ? f - o.velocity : f;
    if (o.shape == ObstacleShape::Sphere) {
      const glm::vec3 d = x - o.position;
      const float r = std::sqrt(dot3(d, d));
      if (!(r > 0.0f)) continue;  // the centre: no direction
      const glm::vec3 n = d * (1.0f / r);
      const float rc = std::max(r, o.radius);
      const float k = sphereStrength(o) / (rc * rc * rc);
      const float un = dot3(u, n);
      out = out + k * (u - (3.0f * un) * n);
      continue;
    }
    const float layer = layerThickness(o);
    if (beyondLayer(o, x, layer)) continue;
    const ObstacleSurface s = obstacleSurface(o, x);
    if (!(s.distance < layer)) continue;
    const float t = std::clamp(s.distance / layer, 0.0f, 1.0f);
    const float w = 1.0f - t * t * (3.0f - 2.0f * t);
    const float un = dot3(u, s.normal);
    out = out - (w * un) * s.normal;
  }
  return out;
}

bool pushOutOfObstacle(const Obstacle& o, glm::vec3& x, glm::vec3& v, const HeightMap* terrain) {
  if (clearOf(o, x)) return false;
  const ObstacleSurface s = obstacleSurface(o, x);
  if (!(s.distance < 0.0f)) return false;
  glm::vec3 n = s.normal;
  glm::vec3 y = x + (kObstacleMargin - s.distance) * n;
  if (terrain && y.z < terrain->heightAt(glm::vec2(y))) {
    y = glm::vec3(x.x, x.y, topAbove(o, x) + kObstacleMargin);
    n = glm::vec3(0.0f, 0.0f, 1.0f);
  }
  x = y;
  const float vn = dot3(v - o.velocity, n);
  if (vn < 0.0f) v = v - ((1.0f + o.restitution) * vn) * n;
  return true;
}

void keepOutOfObstacles(std::span<const Obstacle> obstacles, glm::vec3& x, glm::vec3& v,
                        const HeightMap* terrain) {
  bool pushed = false;
  for (const Obstacle& o : obstacles)
    if (pushOutOfObstacle(o, x, v, terrain)) pushed = true;
  if (!pushed) return;  // x never moved, and was in none
  for (std::size_t pass = 0; pass < obstacles.size(); ++pass) {
    bool rose = false;
    for (const Obstacle& o : obstacles) {
      if (clearOf(o, x) || !(obstacleSurface(o, x).distance < 0.0f)) continue;
      x.z = topAbove(o, x) + kObstacleMargin;
      rose = true;
    }
    if (!rose) return;
  }
}

}  // namespace sandstorm
