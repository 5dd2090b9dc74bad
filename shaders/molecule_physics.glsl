// A molecule's step: the twin of advanceMolecule in
// core/molecules/molecule_physics.cpp, operation for operation, all
// `precise`. Needs particle_physics.glsl (compiled with MOLECULES, for the
// push tool's wind) and molecule_birth.glsl.

// One step of a molecule whose members are m[0 .. n-1] (advanceMolecule);
// `repulsion`: its displacement from its neighbours. False when it dies.
bool advanceMolecule(inout Particle m[kMoleculeMaxMembers], vec3 repulsion) {
  int n = molecule.shape.x;
  precise float life = m[0].positionLife.w - sim.stepParams.x;
  if (life <= 0.0) return false;
  precise float age = m[0].velocityKind.w - m[0].positionLife.w;
  gParticleAge = age;
  bool tracer = sim.modes.x == kMotionTracer;

  vec3 x[kMoleculeMaxMembers], v[kMoleculeMaxMembers], from[kMoleculeMaxMembers],
      moved[kMoleculeMaxMembers];
  float w[kMoleculeMaxMembers];
  for (int j = 0; j < n; ++j) {
    x[j] = m[j].positionLife.xyz;
    from[j] = x[j];
    v[j] = m[j].velocityKind.xyz;
    w[j] = j == 0 ? molecule.mass.y : 1.0;
    integrate(x[j], v[j]);
  }
  // The vane.
  precise vec3 tail = vec3(0.0);
  for (int j = 1; j < n; ++j)
    tail = tail + x[j];
  tail = tail * molecule.pushMore.z;
  precise vec3 headShift = vec3(0.0);
  for (int j = 1; j < n; ++j) {
    precise vec3 axis = (molecule.shape.w != 0 ? tail : x[j]) - x[0];
    precise float len = sqrt(mdot(axis, axis));
    if (!(len > 0.0)) continue;
    precise vec3 along = axis * (1.0 / len);
    precise vec3 stepped = x[j] - from[j];
    precise vec3 turned = (stepped - along * mdot(along, stepped)) * molecule.rest[j].w;
    precise vec3 xj = x[j] + turned;
    x[j] = xj;
    headShift = headShift - turned;
  }
  precise vec3 head = x[0] + headShift * molecule.mass.y;
  x[0] = head;
  for (int j = 0; j < n; ++j)
    moved[j] = x[j];
  if (molecule.repulsion.x != 0.0)
    for (int j = 0; j < n; ++j) {
      precise vec3 xj = x[j] + repulsion;
      x[j] = xj;
    }
  for (int j = 0; j < n; ++j)
    collideMember(x[j], v[j]);

  // The springs, position-based, in order.
  int springCount = molecule.shape.z;
  for (int it = 0; it < molecule.shape.y; ++it) {
    for (int k = 0; k < springCount; ++k) {
      int a = int(molecule.springs[k].x), b = int(molecule.springs[k].y);
      precise vec3 d = x[b] - x[a];
      precise float len = sqrt(mdot(d, d));
      if (!(len > 0.0)) continue;
      precise float s = molecule.mass.w * (len - molecule.springs[k].z) / (len * (w[a] + w[b]));
      precise vec3 c = d * s;
      precise vec3 xa = x[a] + c * w[a];
      precise vec3 xb = x[b] - c * w[b];
      x[a] = xa;
      x[b] = xb;
    }
  }
  if (!tracer) {
    for (int j = 0; j < n; ++j) {
      precise vec3 vj = v[j] + (x[j] - moved[j]) * molecule.motion.y;
      v[j] = vj;
    }
    precise vec3 mean = v[0] * molecule.mass.x;
    for (int j = 1; j < n; ++j)
      mean = mean + v[j];
    mean = mean * molecule.mass.z;
    for (int j = 0; j < n; ++j) {
      precise vec3 vj = v[j] + (mean - v[j]) * molecule.motion.x;
      v[j] = vj;
    }
  }

  if (sim.fieldDims.w != 0) {
    vec3 bmin = sim.domainMin.xyz, bmax = sim.domainMax.xyz;
    if (sim.modes.z == kBoundaryWrap) {
      vec3 local = toLocal(x[0]);
      if (any(lessThan(local, bmin)) || any(greaterThan(local, bmax))) {
        precise vec3 wrapped = local;
        for (int a = 0; a < 3; ++a) {
          precise float e = bmax[a] - bmin[a];
          precise float r = local[a] - bmin[a];
          if (e < 1e30) wrapped[a] = bmin[a] + (r - e * floor(r / e));
        }
        precise vec3 shift = toRoom(wrapped) - x[0];
        for (int j = 0; j < n; ++j) {
          precise vec3 xj = x[j] + shift;
          x[j] = xj;
        }
      }
    } else {
      for (int j = 0; j < n; ++j) {
        vec3 local = toLocal(x[j]);
        if (!(any(lessThan(local, bmin)) || any(greaterThan(local, bmax)))) continue;
        if (sim.modes.z == kBoundaryKill) return false;
        x[j] = toRoom(clamp(local, bmin, bmax));
      }
    }
  }
  if (sim.fieldDims.w != 0 && sim.fieldBlend.z != 0.0) {
    for (int j = 0; j < n; ++j) {
      vec3 local = toLocal(x[j]);
      if (cellValid(false, local) && (sim.fieldBlend.y == 0.0 || cellValid(true, local))) continue;
      if (sim.modes.z != kBoundaryClamp) return false;
      x[j] = m[j].positionLife.xyz;
      v[j] = vec3(0.0);
    }
  }
  for (int j = 0; j < n; ++j) {
    collideMember(x[j], v[j]);
    m[j].positionLife = vec4(x[j], life);
    m[j].velocityKind = vec4(v[j], m[j].velocityKind.w);
  }
  return true;
}
