// A molecule's step: the twin of advanceMolecule in
// core/molecules/molecule_physics.cpp, operation for operation, all
// `precise`. Needs particle_physics.glsl (compiled with MOLECULES, for the
// push tool's wind) and molecule_birth.glsl.

// The shape as constants (MoleculeUpdate compiles a program per complexity):
// MEMBERS, SPRING_COUNT, SPRINGS_A, SPRINGS_B (each spring's two members) and
// SOLID (1 for a shape with faces). With them every loop over members and
// springs unrolls and the members stay in registers (indexed by uniforms,
// they went to local memory).
const int kMembers = MEMBERS;
const int kSprings = SPRING_COUNT;
const int kSpringA[kSprings] = int[](SPRINGS_A);
const int kSpringB[kSprings] = int[](SPRINGS_B);

// One step of a molecule (advanceMolecule) whose members are at x, moving at
// v, with the molecule's life (before the step) and lifetime; `repulsion`:
// its displacement from its neighbours. The includer gives memberStart(j):
// member j's position before the step. False when it dies.
bool advanceMolecule(inout vec3 x[kMembers], inout vec3 v[kMembers], inout float life,
                     float lifetime, vec3 repulsion) {
  precise float left = life - sim.stepParams.x;
  if (left <= 0.0) return false;
  precise float age = lifetime - life;
  gParticleAge = age;
  bool tracer = sim.modes.x == kMotionTracer;

  for (int j = 0; j < kMembers; ++j)
    integrate(x[j], v[j]);
  // The vane.
  precise vec3 tail = vec3(0.0);
  for (int j = 1; j < kMembers; ++j)
    tail = tail + x[j];
  tail = tail * molecule.pushMore.z;
  precise vec3 headShift = vec3(0.0);
  for (int j = 1; j < kMembers; ++j) {
    precise vec3 axis = (SOLID != 0 ? tail : x[j]) - x[0];
    precise float len = sqrt(mdot(axis, axis));
    if (!(len > 0.0)) continue;
    precise vec3 along = axis * (1.0 / len);
    precise vec3 stepped = x[j] - memberStart(j);
    precise vec3 turned = (stepped - along * mdot(along, stepped)) * molecule.rest[j].w;
    precise vec3 xj = x[j] + turned;
    x[j] = xj;
    headShift = headShift - turned;
  }
  precise vec3 head = x[0] + headShift * molecule.mass.y;
  x[0] = head;
  vec3 moved[kMembers];
  for (int j = 0; j < kMembers; ++j)
    moved[j] = x[j];
  if (molecule.repulsion.x != 0.0)
    for (int j = 0; j < kMembers; ++j) {
      precise vec3 xj = x[j] + repulsion;
      x[j] = xj;
    }

  // The springs, position-based, in order.
  for (int it = 0; it < molecule.shape.y; ++it) {
    for (int k = 0; k < kSprings; ++k) {
      int a = kSpringA[k], b = kSpringB[k];
      float wa = a == 0 ? molecule.mass.y : 1.0, wb = b == 0 ? molecule.mass.y : 1.0;
      precise vec3 d = x[b] - x[a];
      precise float len = sqrt(mdot(d, d));
      if (!(len > 0.0)) continue;
      precise float s = molecule.springs[k].w * (len - molecule.springs[k].z) / len;
      precise vec3 c = d * s;
      precise vec3 xa = x[a] + c * wa;
      precise vec3 xb = x[b] - c * wb;
      x[a] = xa;
      x[b] = xb;
    }
  }
  if (!tracer) {
    for (int j = 0; j < kMembers; ++j) {
      precise vec3 vj = v[j] + (x[j] - moved[j]) * molecule.motion.y;
      v[j] = vj;
    }
    precise vec3 mean = v[0] * molecule.mass.x;
    for (int j = 1; j < kMembers; ++j)
      mean = mean + v[j];
    mean = mean * molecule.mass.z;
    for (int j = 0; j < kMembers; ++j) {
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
        for (int j = 0; j < kMembers; ++j) {
          precise vec3 xj = x[j] + shift;
          x[j] = xj;
        }
      }
    } else {
      for (int j = 0; j < kMembers; ++j) {
        vec3 local = toLocal(x[j]);
        if (!(any(lessThan(local, bmin)) || any(greaterThan(local, bmax)))) continue;
        if (sim.modes.z == kBoundaryKill) return false;
        x[j] = toRoom(clamp(local, bmin, bmax));
      }
    }
  }
  if (sim.fieldDims.w != 0 && sim.fieldBlend.z != 0.0) {
    for (int j = 0; j < kMembers; ++j) {
      vec3 local = toLocal(x[j]);
      if (cellValid(false, local) && (sim.fieldBlend.y == 0.0 || cellValid(true, local))) continue;
      if (sim.modes.z != kBoundaryClamp) return false;
      x[j] = memberStart(j);
      v[j] = vec3(0.0);
    }
  }
  for (int j = 0; j < kMembers; ++j)
    collideMember(x[j], v[j]);
  life = left;
  return true;
}
