#include "core/sim/particle_physics.h"

#include <algorithm>
#include <cmath>

#include "core/obstacles/obstacle_physics.h"

namespace sandstorm {
namespace {

constexpr float kMinLifetime = 1e-3f;
constexpr std::uint32_t kBallTries = 16;

// A point uniform in the unit ball (or, flat, the unit disc): the first of up
// to 16 candidates from the cube that falls inside. Rejection needs no sin,
// cos or cube root, whose last bits differ between GPUs and the CPU. After 16
// misses (p < 1e-5 for the ball) the last candidate, halved, stands in.
glm::vec3 inUnitBall(Seed seed, std::uint32_t frame, std::uint32_t e, std::uint32_t k,
                     RngStream stream, bool flat) {
  glm::vec3 c(0.0f);
  for (std::uint32_t t = 0; t < kBallTries; ++t) {
    c = 2.0f * glm::vec3(randomUniform(seed, frame, e, k, stream, t)) - 1.0f;
    if (flat) c.z = 0.0f;
    if (c.x * c.x + c.y * c.y + c.z * c.z <= 1.0f) return c;
  }
  return c * 0.5f;
}

struct Slope {
  glm::vec3 dx, dv;
};

Slope derivative(const glm::vec3& x, const glm::vec3& v, const PhysicsInputs& in, float age,
                 const Forcing& forcing) {
  glm::vec3 f = fieldAt(x, in, v, age);
  if (forcing.push) f = f + pushWind(x, forcing);
  switch (in.settings.motion) {
    case MotionModel::Tracer:
      return {f, glm::vec3(0.0f)};
    case MotionModel::Force:
      return {v, f + in.settings.gravity};
    case MotionModel::Drag:
      return {v, (f - v) * (1.0f / in.settings.dragTime) + in.settings.gravity};
  }
  return {glm::vec3(0.0f), glm::vec3(0.0f)};
}

}  // namespace

glm::vec3 pushWind(const glm::vec3& x, const Forcing& forcing) {
  const glm::vec3 d = x - forcing.pushCentre;
  const float r = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  if (!(r > 0.0f && r < forcing.pushRadius)) return glm::vec3(0.0f);
  const float s = forcing.pushSpeed * (1.0f - r / forcing.pushRadius) / r;
  return d * s;
}

// Moves (x, v) by one step. Euler is the thesis's: velocity first, then the
// position with the new velocity (semi-implicit, which keeps orbits bounded).
void integrate(glm::vec3& x, glm::vec3& v, const PhysicsInputs& in, float age,
               const Forcing& forcing) {
  const float h = in.dt;
  const bool tracer = in.settings.motion == MotionModel::Tracer;
  const Slope k1 = derivative(x, v, in, age, forcing);
  if (in.settings.integrator == Integrator::Euler) {
    v = tracer ? k1.dx : v + h * k1.dv;
    x = x + h * v;
    return;
  }
  glm::vec3 dx, dv;
  const float h2 = 0.5f * h;
  const Slope k2 = derivative(x + h2 * k1.dx, v + h2 * k1.dv, in, age, forcing);
  if (in.settings.integrator == Integrator::RK2) {
    dx = k2.dx;
    dv = k2.dv;
  } else {
    const Slope k3 = derivative(x + h2 * k2.dx, v + h2 * k2.dv, in, age, forcing);
    const Slope k4 = derivative(x + h * k3.dx, v + h * k3.dv, in, age, forcing);
    dx = (k1.dx + 2.0f * k2.dx + 2.0f * k3.dx + k4.dx) * (1.0f / 6.0f);
    dv = (k1.dv + 2.0f * k2.dv + 2.0f * k3.dv + k4.dv) * (1.0f / 6.0f);
  }
  x = x + h * dx;
  // A tracer's velocity is the slope it moved along.
  v = tracer ? dx : v + h * dv;
}

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
  return fieldAt(x, in, glm::vec3(0.0f), 0.0f);
}

glm::vec3 fieldAt(const glm::vec3& x, const PhysicsInputs& in, const glm::vec3& v, float age) {
  glm::vec3 room(0.0f);
  if (in.field) {
    const glm::vec3 local = in.placement.toLocal(x);
    glm::vec3 f;
    if (in.expression) {
      f = in.expression->evaluate(local, in.time, v, age);
    } else if (in.sparse) {
      f = in.sparse->sample(local);
    } else if (in.nextField && in.pointwiseBlend) {
      f = in.field->sampleBlended(*in.nextField, in.blend, local);
    } else {
      f = in.field->sample(local);
      if (in.nextField) f = f + (in.nextField->sample(local) - f) * in.blend;
    }
    room = in.settings.fieldStrength * in.placement.vectorToRoom(f);
  }
  if (in.obstacles.empty()) return room;
  return flowAroundObstacles(room, x, in.obstacles, in.settings.motion != MotionModel::Force);
}

Particle birth(const Emitter& e, Seed seed, std::uint32_t frame, std::uint32_t emitterIndex,
               std::uint32_t index) {
  const glm::vec4 u = randomUniform(seed, frame, emitterIndex, index, RngStream::kBirth);
  glm::vec3 offset(0.0f);
  switch (e.shape) {
    case EmitterShape::Box:
      offset = (glm::vec3(u) - 0.5f) * glm::vec3(e.width, e.depth, e.height);
      break;
    case EmitterShape::Sphere:
    case EmitterShape::Disc:
      offset = e.radius * inUnitBall(seed, frame, emitterIndex, index, RngStream::kBirthBall,
                                     e.shape == EmitterShape::Disc);
      break;
    case EmitterShape::Point:
      break;
  }
  glm::vec3 velocity = e.velocity;
  if (e.spread > 0.0f)
    velocity = velocity + e.spread * inUnitBall(seed, frame, emitterIndex, index,
                                                RngStream::kVelocityBall, false);
  const float life = std::max(e.lifetime + e.lifetimeVariance * (2.0f * u.w - 1.0f), kMinLifetime);
  return Particle{glm::vec4(e.position + offset, life), glm::vec4(velocity, life)};
}

void settleNewborn(Particle& p, const PhysicsInputs& in) {
  if (in.obstacles.empty()) return;
  glm::vec3 x = p.position(), v = p.velocity();
  keepOutOfObstacles(in.obstacles, x, v, in.settings.groundCollision ? in.terrain : nullptr);
  p.positionLife = glm::vec4(x, p.positionLife.w);
  p.velocityKind = glm::vec4(v, p.velocityKind.w);
}

bool advance(Particle& p, const PhysicsInputs& in) {
  const float life = p.positionLife.w - in.dt;
  if (life <= 0.0f) return false;

  glm::vec3 x = p.position();
  glm::vec3 v = p.velocity();
  const float age = p.velocityKind.w - p.positionLife.w;  // lived, before this step
  integrate(x, v, in, age);

  if (in.field) {
    const Box b = particleDomain(*in.field);
    const glm::vec3 local = in.placement.toLocal(x);
    if (!b.contains(local)) {
      switch (in.settings.boundary) {
        case BoundaryMode::Kill:
          return false;
        case BoundaryMode::Clamp:
          x = in.placement.toRoom(glm::clamp(local, b.min, b.max));
          break;
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
  // Cells the field has no data for (its validity mask) are outside too:
  // killed, or held where they were (clamp); wrapping has nowhere to go.
  if (in.field && (in.field->hasValidity() || (in.nextField && in.nextField->hasValidity()))) {
    const glm::vec3 local = in.placement.toLocal(x);
    if (!in.field->cellValid(local) || (in.nextField && !in.nextField->cellValid(local))) {
      if (in.settings.boundary != BoundaryMode::Clamp) return false;
      x = p.position();
      v = glm::vec3(0.0f);
    }
  }
  const HeightMap* ground = in.settings.groundCollision ? in.terrain : nullptr;
  if (ground) {
    const float height = ground->heightAt(glm::vec2(x));
    if (x.z < height) {
      x.z = height;
      if (v.z < 0.0f) v.z = -v.z * in.settings.restitution;
    }
  }
  // Out of the obstacles, in order (after the ground, which they stand on).
  keepOutOfObstacles(in.obstacles, x, v, ground);
  p.positionLife = glm::vec4(x, life);
  p.velocityKind = glm::vec4(v, p.velocityKind.w);
  return true;
}

}  // namespace sandstorm
