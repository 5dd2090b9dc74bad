// A molecule's birth and its members' collisions: the twins of
// birthMolecule, settleNewbornMolecule and collide in
// core/molecules/molecule_physics.cpp, all `precise`. Needs rng.glsl,
// sim_block.glsl, molecule_block.glsl and terrain_height.glsl; OBSTACLES
// programs also obstacles.glsl.

const uint kStreamMoleculeTurn = 48u;  // 48..79

float mdot(vec3 a, vec3 b) {
  precise float d = a.x * b.x + a.y * b.y + a.z * b.z;
  return d;
}

vec3 mcross(vec3 a, vec3 b) {
  precise vec3 c = vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  return c;
}

// A uniform unit quaternion (w, x, y, z) (randomTurn in the C++).
vec4 randomTurn(uvec2 seed, uint frame, uint e, uint k) {
  precise vec4 c = vec4(1.0, 0.0, 0.0, 0.0);
  precise float r2 = 1.0;
  for (uint t = 0u; t < 32u; ++t) {
    c = 2.0 * randomUniform(seed, frame, e, k, kStreamMoleculeTurn + t) - 1.0;
    r2 = c.x * c.x + c.y * c.y + c.z * c.z + c.w * c.w;
    if (r2 <= 1.0 && r2 > 1e-4) break;
  }
  if (!(r2 > 0.0)) return vec4(1.0, 0.0, 0.0, 0.0);
  precise float inv = 1.0 / sqrt(r2);
  precise vec4 q = c * inv;
  return q;
}

vec3 turnBy(vec4 q, vec3 p) {
  vec3 axis = q.yzw;
  precise vec3 t = 2.0 * mcross(axis, p);
  precise vec3 r = p + q.x * t + mcross(axis, t);
  return r;
}

// Member j of a newborn molecule turned by q about `centre` (birthMolecule).
Particle birthMember(vec4 q, Particle centre, int j) {
  precise vec3 offset = turnBy(q, molecule.rest[j].xyz * molecule.motion.z);
  precise vec3 x = centre.positionLife.xyz + offset;
  Particle p;
  p.positionLife = vec4(x, centre.positionLife.w);
  p.velocityKind = centre.velocityKind;
  return p;
}

bool moleculeGround() {
  return sim.modes.w != 0 && sim.terrainDims.z != 0;
}

// The ground and the obstacles put a member out (collide in the C++).
void collideMember(inout vec3 x, inout vec3 v) {
  if (moleculeGround()) {
    float height = terrainHeight(x.xy);
    if (x.z < height) {
      x.z = height;
      if (v.z < 0.0) {
        precise float bounced = -v.z * sim.stepParams.z;
        v.z = bounced;
      }
    }
  }
#ifdef OBSTACLES
  if (sim.obstacleCount.x != 0) keepOutOfObstacles(x, v, moleculeGround());
#endif
}

// A newborn molecule lifted whole out of the ground, then its members out of
// the obstacles (settleNewbornMolecule).
void settleNewbornMolecule(inout Particle m[kMoleculeMaxMembers]) {
  int n = molecule.shape.x;
  precise float lift = 0.0;
  if (moleculeGround())
    for (int j = 0; j < n; ++j) lift = max(lift, terrainHeight(m[j].positionLife.xy) - m[j].positionLife.z);
  for (int j = 0; j < n; ++j) {
    precise vec3 x = m[j].positionLife.xyz;
    x.z = x.z + lift;
    vec3 v = m[j].velocityKind.xyz;
#ifdef OBSTACLES
    if (sim.obstacleCount.x != 0) keepOutOfObstacles(x, v, moleculeGround());
#endif
    m[j].positionLife.xyz = x;
    m[j].velocityKind.xyz = v;
  }
}
