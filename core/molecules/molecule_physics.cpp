#include "core/molecules/molecule_physics.h"

#include <algorithm>
#include <cmath>

#include "core/obstacles/obstacle_physics.h"

namespace sandstorm {
namespace {

constexpr std::uint32_t kTurnTries = 32;

float dot3(const glm::vec3& a, const glm::vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

glm::vec3 cross3(const glm::vec3& a, const glm::vec3& b) {
  return glm::vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

// A uniform unit quaternion (w, x, y, z): a point uniform in the 4-ball,
// normalised (the first of 32 candidates from the cube that falls inside and
// away from the centre; after 32 misses, p < 1e-5, the last, normalised).
glm::vec4 randomTurn(Seed seed, std::uint32_t frame, std::uint32_t e, std::uint32_t k) {
  glm::vec4 c(1.0f, 0.0f, 0.0f, 0.0f);
  float r2 = 1.0f;
  for (std::uint32_t t = 0; t < kTurnTries; ++t) {
    c = 2.0f * randomUniform(seed, frame, e, k, RngStream::kMoleculeTurn, t) - 1.0f;
    r2 = c.x * c.x + c.y * c.y + c.z * c.z + c.w * c.w;
    if (r2 <= 1.0f && r2 > 1e-4f) break;
  }
  if (!(r2 > 0.0f)) return glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
  const float inv = 1.0f / std::sqrt(r2);
  return c * inv;
}

// p turned by the unit quaternion q = (w, x, y, z): p + w t + q.xyz x t, t = 2 q.xyz x p.
glm::vec3 turn(const glm::vec4& q, const glm::vec3& p) {
  const glm::vec3 axis(q.y, q.z, q.w);
  const glm::vec3 t = 2.0f * cross3(axis, p);
  return p + q.x * t + cross3(axis, t);
}

using Members = std::array<glm::vec3, MoleculeSettings::kMaxComplexity>;

// The ground and the obstacles put each member out, as they do a particle.
void collide(Members& x, Members& v, int n, const PhysicsInputs& in) {
  const HeightMap* ground = in.settings.groundCollision ? in.terrain : nullptr;
  for (int j = 0; j < n; ++j) {
    if (ground) {
      const float height = ground->heightAt(glm::vec2(x[j]));
      if (x[j].z < height) {
        x[j].z = height;
        if (v[j].z < 0.0f) v[j].z = -v[j].z * in.settings.restitution;
      }
    }
    keepOutOfObstacles(in.obstacles, x[j], v[j], ground);
  }
}

}  // namespace

MoleculeParams moleculeParams(const MoleculeSettings& s, float dt) {
  MoleculeParams p;
  const MoleculeShape& shape = moleculeShape(s.complexity);
  p.members = shape.members;
  p.iterations = std::max(s.iterations, 1);
  p.headMass = std::max(s.headMass, 1.0f);
  p.invHeadMass = 1.0f / p.headMass;
  const float total = p.headMass + float(p.members - 1);
  p.invTotalMass = 1.0f / total;
  p.invMembers = 1.0f / float(p.members);
  p.invTailMembers = 1.0f / float(p.members - 1);
  const float vane = std::clamp(s.vane, 0.0f, 1.0f);
  p.solid = !shape.faces.empty();
  for (int j = 0; j < p.members; ++j)
    p.vaneReach[std::size_t(j)] = vane * glm::distance(shape.rest[std::size_t(j)], shape.rest[0]);
  const float keep = std::clamp(1.0f - s.stiffness, 0.0f, 1.0f);
  p.passStiffness = float(1.0 - std::pow(double(keep), 1.0 / double(p.iterations)));
  p.damping = std::clamp(s.damping, 0.0f, 1.0f);
  p.invDt = dt > 0.0f ? 1.0f / dt : 0.0f;
  for (std::size_t k = 0; k < shape.springs.size(); ++k) {
    const MoleculeSpring& spring = shape.springs[k];
    p.springLength[k] = spring.rest * s.size;
    const float wa = spring.a == 0 ? p.invHeadMass : 1.0f,
                wb = spring.b == 0 ? p.invHeadMass : 1.0f;
    p.springFactor[k] = p.passStiffness / (wa + wb);
  }
  p.push.push = s.push && s.pushSpeed > 0.0f;
  p.push.pushCentre = s.pushPosition;
  p.push.pushRadius = s.pushRadius;
  p.push.pushSpeed = s.pushSpeed;
  p.repulsion = s.repulsion && s.repulsionStrength > 0.0f;
  p.repulsionRadius = s.repulsionRadius;
  p.repulsionShare = 0.5f * s.repulsionStrength;
  return p;
}

void birthMolecule(const Emitter& emitter, Seed seed, std::uint32_t frame,
                   std::uint32_t emitterIndex, std::uint32_t index, const MoleculeShape& shape,
                   float size, std::span<Particle> members) {
  const Particle centre = birth(emitter, seed, frame, emitterIndex, index);
  const glm::vec4 q = randomTurn(seed, frame, emitterIndex, index);
  for (int j = 0; j < shape.members; ++j) {
    const glm::vec3 offset = turn(q, shape.rest[std::size_t(j)] * size);
    members[std::size_t(j)] =
        Particle{glm::vec4(centre.position() + offset, centre.life()), centre.velocityKind};
  }
}

void settleNewbornMolecule(std::span<Particle> members, const PhysicsInputs& in) {
  // Lifted whole out of the ground (member by member would crush it), then
  // out of the obstacles member by member, as particles are.
  const HeightMap* ground = in.settings.groundCollision ? in.terrain : nullptr;
  float lift = 0.0f;
  if (ground)
    for (const Particle& p : members)
      lift = std::max(lift, ground->heightAt(glm::vec2(p.position())) - p.position().z);
  for (Particle& p : members) {
    glm::vec3 x = p.position(), v = p.velocity();
    x.z = x.z + lift;
    keepOutOfObstacles(in.obstacles, x, v, ground);
    p.positionLife = glm::vec4(x, p.positionLife.w);
    p.velocityKind = glm::vec4(v, p.velocityKind.w);
  }
}

glm::vec3 moleculeCentre(std::span<const Particle> members) {
  glm::vec3 sum(0.0f);
  for (const Particle& p : members)
    sum = sum + p.position();
  return sum * (1.0f / float(members.size()));
}

bool advanceMolecule(std::span<Particle> m, const PhysicsInputs& in, const MoleculeParams& params,
                     const glm::vec3& repulsion) {
  const int n = params.members;
  const float life = m[0].positionLife.w - in.dt;
  if (life <= 0.0f) return false;
  const float age = m[0].velocityKind.w - m[0].positionLife.w;  // lived, before this step
  const MoleculeShape& shape = moleculeShape(n);
  const bool tracer = in.settings.motion == MotionModel::Tracer;

  Members x, v, from, moved;
  std::array<float, MoleculeSettings::kMaxComplexity> w;
  const Forcing forcing = params.push;
  for (int j = 0; j < n; ++j) {
    x[j] = from[j] = m[std::size_t(j)].position();
    v[j] = m[std::size_t(j)].velocity();
    w[j] = j == 0 ? params.invHeadMass : 1.0f;
    integrate(x[j], v[j], in, age, forcing);
  }
  // The vane: each member's step across its axis, times its reach, turns the
  // molecule towards the step; the head takes the opposite share by its
  // mass, so the molecule's mass-weighted mean moves as the flow moves it.
  // A solid shape's axis is the molecule's (from the head to the others'
  // mean: members off it would be pulled apart), a chain member's its arm
  // from the head (a bent chain straightens).
  glm::vec3 tail(0.0f);
  for (int j = 1; j < n; ++j)
    tail = tail + x[j];
  tail = tail * params.invTailMembers;
  glm::vec3 headShift(0.0f);
  for (int j = 1; j < n; ++j) {
    const glm::vec3 axis = (params.solid ? tail : x[j]) - x[0];
    const float len = std::sqrt(dot3(axis, axis));
    if (!(len > 0.0f)) continue;
    const glm::vec3 along = axis * (1.0f / len);
    const glm::vec3 step = x[j] - from[j];
    const glm::vec3 turn = (step - along * dot3(along, step)) * params.vaneReach[std::size_t(j)];
    x[j] = x[j] + turn;
    headShift = headShift - turn;
  }
  x[0] = x[0] + headShift * params.invHeadMass;
  for (int j = 0; j < n; ++j)
    moved[j] = x[j];
  if (params.repulsion)
    for (int j = 0; j < n; ++j)
      x[j] = x[j] + repulsion;

  // The springs, position-based, in order (Gauss-Seidel).
  for (int it = 0; it < params.iterations; ++it) {
    for (std::size_t k = 0; k < shape.springs.size(); ++k) {
      const int a = shape.springs[k].a, b = shape.springs[k].b;
      const glm::vec3 d = x[b] - x[a];
      const float len = std::sqrt(dot3(d, d));
      if (!(len > 0.0f)) continue;
      const float s = params.springFactor[k] * (len - params.springLength[k]) / len;
      const glm::vec3 c = d * s;
      x[a] = x[a] + c * w[a];
      x[b] = x[b] - c * w[b];
    }
  }
  if (!tracer) {
    for (int j = 0; j < n; ++j)
      v[j] = v[j] + (x[j] - moved[j]) * params.invDt;
    // The mass-weighted mean velocity: the molecule's, which damping keeps.
    glm::vec3 mean = v[0] * params.headMass;
    for (int j = 1; j < n; ++j)
      mean = mean + v[j];
    mean = mean * params.invTotalMass;
    for (int j = 0; j < n; ++j)
      v[j] = v[j] + (mean - v[j]) * params.damping;
  }

  if (in.field) {
    const Box b = particleDomain(*in.field);
    if (in.settings.boundary == BoundaryMode::Wrap) {
      const glm::vec3 head = in.placement.toLocal(x[0]);
      if (!b.contains(head)) {
        glm::vec3 wrapped = head;
        for (int a = 0; a < 3; ++a) {
          const float e = b.max[a] - b.min[a];
          const float r = head[a] - b.min[a];
          if (e < kUnbounded) wrapped[a] = b.min[a] + (r - e * std::floor(r / e));
        }
        const glm::vec3 shift = in.placement.toRoom(wrapped) - x[0];
        for (int j = 0; j < n; ++j)
          x[j] = x[j] + shift;
      }
    } else {
      for (int j = 0; j < n; ++j) {
        const glm::vec3 local = in.placement.toLocal(x[j]);
        if (b.contains(local)) continue;
        if (in.settings.boundary == BoundaryMode::Kill) return false;
        x[j] = in.placement.toRoom(glm::clamp(local, b.min, b.max));
      }
    }
  }
  if (in.field && (in.field->hasValidity() || (in.nextField && in.nextField->hasValidity()))) {
    for (int j = 0; j < n; ++j) {
      const glm::vec3 local = in.placement.toLocal(x[j]);
      if (in.field->cellValid(local) && (!in.nextField || in.nextField->cellValid(local))) continue;
      if (in.settings.boundary != BoundaryMode::Clamp) return false;
      x[j] = m[std::size_t(j)].position();
      v[j] = glm::vec3(0.0f);
    }
  }
  collide(x, v, n, in);
  for (int j = 0; j < n; ++j) {
    m[std::size_t(j)].positionLife = glm::vec4(x[j], life);
    m[std::size_t(j)].velocityKind = glm::vec4(v[j], m[std::size_t(j)].velocityKind.w);
  }
  return true;
}

}  // namespace sandstorm
