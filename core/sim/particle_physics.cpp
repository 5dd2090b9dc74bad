#include "core/sim/particle_physics.h"

#include <algorithm>
#include <cmath>

namespace sandstorm {
namespace {

constexpr float kTwoPi = 6.28318530717958647692f;
constexpr float kMinLifetime = 1e-3f;

// A unit vector from two uniform numbers (uniform on the sphere).
glm::vec3 unitVector(float a, float b) {
  const float z = 2.0f * a - 1.0f;
  const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = kTwoPi * b;
  return glm::vec3(s * std::cos(phi), s * std::sin(phi), z);
}

// A point uniform in the unit ball from three uniform numbers.
glm::vec3 inUnitBall(const glm::vec3& u) { return std::cbrt(u.x) * unitVector(u.y, u.z); }

glm::vec3 birthOffset(const Emitter& e, const glm::vec4& u) {
  switch (e.shape) {
    case EmitterShape::Box:
      return (glm::vec3(u) - 0.5f) * glm::vec3(e.width, e.depth, e.height);
    case EmitterShape::Sphere: return e.radius * inUnitBall(glm::vec3(u));
    case EmitterShape::Disc: {
      const float r = e.radius * std::sqrt(u.x);
      const float phi = kTwoPi * u.y;
      return glm::vec3(r * std::cos(phi), r * std::sin(phi), 0.0f);
    }
    case EmitterShape::Point: return glm::vec3(0.0f);
  }
  return glm::vec3(0.0f);
}

struct Slope {
  glm::vec3 dx, dv;
};

Slope derivative(const glm::vec3& x, const glm::vec3& v, const PhysicsInputs& in) {
  const glm::vec3 f = fieldAt(x, in);
  switch (in.settings.motion) {
    case MotionModel::Tracer: return {f, glm::vec3(0.0f)};
    case MotionModel::Force: return {v, f + in.settings.gravity};
    case MotionModel::Drag:
      return {v, (f - v) * (1.0f / in.settings.dragTime) + in.settings.gravity};
  }
  return {glm::vec3(0.0f), glm::vec3(0.0f)};
}

// Moves (x, v) by one step. Euler is the thesis's: velocity first, then the
// position with the new velocity (semi-implicit, which keeps orbits bounded).
void integrate(glm::vec3& x, glm::vec3& v, const PhysicsInputs& in) {
  const float h = in.dt;
  const bool tracer = in.settings.motion == MotionModel::Tracer;
  const Slope k1 = derivative(x, v, in);
  if (in.settings.integrator == Integrator::Euler) {
    v = tracer ? k1.dx : v + h * k1.dv;
    x = x + h * v;
    return;
  }
  glm::vec3 dx, dv;
  const float h2 = 0.5f * h;
  const Slope k2 = derivative(x + h2 * k1.dx, v + h2 * k1.dv, in);
  if (in.settings.integrator == Integrator::RK2) {
    dx = k2.dx;
    dv = k2.dv;
  } else {
    const Slope k3 = derivative(x + h2 * k2.dx, v + h2 * k2.dv, in);
    const Slope k4 = derivative(x + h * k3.dx, v + h * k3.dv, in);
    dx = (k1.dx + 2.0f * k2.dx + 2.0f * k3.dx + k4.dx) * (1.0f / 6.0f);
    dv = (k1.dv + 2.0f * k2.dv + 2.0f * k3.dv + k4.dv) * (1.0f / 6.0f);
  }
  x = x + h * dx;
  // A tracer's velocity is the slope it moved along.
  v = tracer ? dx : v + h * dv;
}

}  // namespace

Box particleDomain(const VectorField& field) {
  Box b = field.bounds();
  for (int a = 0; a < 3; ++a) {
    if (field.dims()[a] == 1) {
      b.min[a] = -kUnbounded;
      b.max[a] = kUnbounded;
    }
  }
  return b;
}

glm::vec3 fieldAt(const glm::vec3& x, const PhysicsInputs& in) {
  if (!in.field) return glm::vec3(0.0f);
  const glm::vec3 local = in.placement.toLocal(x);
  return in.settings.fieldStrength * in.placement.vectorToRoom(in.field->sample(local));
}

Particle birth(const Emitter& e, Seed seed, std::uint32_t frame, std::uint32_t emitterIndex,
               std::uint32_t index) {
  const glm::vec4 u = randomUniform(seed, frame, emitterIndex, index, RngStream::kBirth0);
  const glm::vec4 w = randomUniform(seed, frame, emitterIndex, index, RngStream::kBirth1);
  const float life = std::max(e.lifetime + e.lifetimeVariance * (2.0f * u.w - 1.0f), kMinLifetime);
  const glm::vec3 position = e.position + birthOffset(e, u);
  const glm::vec3 velocity = e.velocity + e.spread * inUnitBall(glm::vec3(w));
  return Particle{glm::vec4(position, life), glm::vec4(velocity, life)};
}

bool advance(Particle& p, const PhysicsInputs& in) {
  const float life = p.positionLife.w - in.dt;
  if (life <= 0.0f) return false;

  glm::vec3 x = p.position();
  glm::vec3 v = p.velocity();
  integrate(x, v, in);

  if (in.field) {
    const Box b = particleDomain(*in.field);
    const glm::vec3 local = in.placement.toLocal(x);
    if (!b.contains(local)) {
      switch (in.settings.boundary) {
        case BoundaryMode::Kill: return false;
        case BoundaryMode::Clamp: x = in.placement.toRoom(glm::clamp(local, b.min, b.max)); break;
        case BoundaryMode::Wrap: {
          glm::vec3 wrapped = local;
          for (int a = 0; a < 3; ++a) {
            const float e = b.max[a] - b.min[a];
            const float r = local[a] - b.min[a];
            if (e < kUnbounded) wrapped[a] = b.min[a] + (r - e * std::floor(r / e));
          }
          x = in.placement.toRoom(wrapped);
          break;
        }
      }
    }
  }
  if (in.settings.groundCollision && in.terrain) {
    const float ground = in.terrain->heightAt(glm::vec2(x));
    if (x.z < ground) {
      x.z = ground;
      if (v.z < 0.0f) v.z = -v.z * in.settings.restitution;
    }
  }
  p.positionLife = glm::vec4(x, life);
  p.velocityKind = glm::vec4(v, p.velocityKind.w);
  return true;
}

}  // namespace sandstorm
