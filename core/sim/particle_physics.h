// The per-particle rules, shared word for word with the shaders:
// birth() with shaders/particle_birth.glsl, advance() with
// shaders/particle_physics.glsl. The reference simulator calls these; the GPU
// backends run the GLSL twins. Keep each pair in step: the GPU/CPU agreement
// tests compare them.
#pragma once

#include <cstdint>
#include <vector>

#include "core/expr/field_expression.h"
#include "core/field/field_placement.h"
#include "core/field/height_map.h"
#include "core/field/sparse_field.h"
#include "core/field/vector_field.h"
#include "core/obstacles/obstacle.h"
#include "core/sim/counter_rng.h"
#include "core/sim/emitter.h"
#include "core/sim/particle.h"
#include "core/sim/sim_settings.h"

namespace sandstorm {

// Everything advance() reads besides the particle.
struct PhysicsInputs {
  const VectorField* field = nullptr;
  // A time-varying field's next frame (same grid) and the weight towards it:
  // the field is field + (next - field) * blend.
  const VectorField* nextField = nullptr;
  float blend = 0.0f;
  // How the pair is blended: sampled each and the samples blended, or
  // (pointwiseBlend) blended point by point into one grid that is sampled
  // (VectorField::sampleBlended), as the compute backend does
  // (ParticleBackend::blendsPairPointwise).
  bool pointwiseBlend = false;
  // A sparse grid sampled in place of `field` (whose bounds are its bounds
  // and still bound the particles), or null.
  const SparseField* sparse = nullptr;
  FieldPlacement placement;
  const HeightMap* terrain = nullptr;
  SimSettings settings;
  float dt = 0.0f;  // simulated seconds this frame
  // The solids the flow goes around and particles bounce off
  // (collisionShapes(state, terrain), core/obstacles/collision_shapes.h).
  std::vector<Obstacle> obstacles;
  // field.mode = expression: the field written at run time, in place of the
  // grid (whose bounds still bound the particles); `time` is its t.
  const FieldExpression* expression = nullptr;
  float time = 0.0f;
};

// What a body's member feels besides the field (molecules, core/molecules/):
// the push tool's wind (pushWind). A particle's is the default: nothing.
struct Forcing {
  bool push = false;
  glm::vec3 pushCentre{0.0f};
  float pushRadius = 0.0f;
  float pushSpeed = 0.0f;
};

// The push tool's wind at x: outward from its centre at pushSpeed there,
// falling linearly to 0 at pushRadius; 0 beyond (and at the centre).
glm::vec3 pushWind(const glm::vec3& x, const Forcing& forcing);

// Moves (x, v) through the field by one step of in.settings' motion model and
// integrator (advance()'s motion, without ageing or bounds).
void integrate(glm::vec3& x, glm::vec3& v, const PhysicsInputs& in, float age,
               const Forcing& forcing = {});

// Particle number `index` of emitter `emitterIndex` born in frame `frame`.
Particle birth(const Emitter& emitter, Seed seed, std::uint32_t frame, std::uint32_t emitterIndex,
               std::uint32_t index);

// A newborn particle put out of the obstacles (keepOutOfObstacles), so none
// is born inside one.
void settleNewborn(Particle& p, const PhysicsInputs& in);

// Ages, moves and bounds one particle. Returns false when it dies.
bool advance(Particle& p, const PhysicsInputs& in);

// Extents at or beyond this are unbounded.
inline constexpr float kUnbounded = 1e30f;

// Where particles may go, in field coordinates: the field's bounds, unbounded
// along axes of a single grid point (a 2D slice extends up and down).
Box particleDomain(const VectorField& field);

// The field as the particles feel it at room position x: strength * field,
// carried through the placement (zero when there is no field), and turned
// around the obstacles (flowAroundObstacles).
glm::vec3 fieldAt(const glm::vec3& x, const PhysicsInputs& in);
// The same for a particle moving at v, `age` seconds old (a field expression reads them).
glm::vec3 fieldAt(const glm::vec3& x, const PhysicsInputs& in, const glm::vec3& v, float age);

}  // namespace sandstorm
