// Birth of a particle: the twin of birth() in core/sim/particle_physics.cpp.
// Needs rng.glsl and sim_block.glsl.

// The first of up to 16 candidates from the cube inside the unit ball (or
// disc); exact arithmetic only, so every GPU and the CPU pick the same one.
vec3 inUnitBall(uvec2 seed, uint frame, uint e, uint k, uint stream, bool planar) {
  precise vec3 c = vec3(0.0);
  for (uint t = 0u; t < 16u; ++t) {
    c = 2.0 * randomUniform(seed, frame, e, k, stream + t).xyz - 1.0;
    if (planar) c.z = 0.0;
    precise float r2 = c.x * c.x + c.y * c.y + c.z * c.z;
    if (r2 <= 1.0) return c;
  }
  return c * 0.5;
}

Particle birth(int e, uint k) {
  EmitterBlock em = sim.emitters[e];
  uvec2 seed = sim.frameSeed.yz;
  uint frame = sim.frameSeed.x;
  vec4 u = randomUniform(seed, frame, uint(e), k, kStreamBirth);
  precise vec3 offset = vec3(0.0);
  int shape = em.shapeCount.x;
  if (shape == kShapeBox) {
    offset = (u.xyz - 0.5) * em.size.xyz;
  } else if (shape == kShapeSphere || shape == kShapeDisc) {
    offset = em.size.w * inUnitBall(seed, frame, uint(e), k, kStreamBirthBall, shape == kShapeDisc);
  }
  precise vec3 velocity = em.velocity.xyz;
  if (em.life.z > 0.0)
    velocity = velocity + em.life.z * inUnitBall(seed, frame, uint(e), k, kStreamVelocityBall, false);
  precise float life = max(em.life.x + em.life.y * (2.0 * u.w - 1.0), 1e-3);
  precise vec3 position = em.position.xyz + offset;
  Particle p;
  p.positionLife = vec4(position, life);
  p.velocityKind = vec4(velocity, life);
  return p;
}
