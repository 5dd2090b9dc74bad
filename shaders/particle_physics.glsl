// Per-particle rules: the twin of core/sim/particle_physics.cpp. Same
// operations in the same order, all `precise`, so llvmpipe and the CPU agree to
// the bit. Needs sim_block.glsl. OBSTACLES programs add the obstacles
// (obstacles.glsl); the others ignore them, so a host with obstacles in the
// block must use an OBSTACLES program, or an OBSTACLE_FLOW one (the flow
// around them only) followed by obstacle_collide.comp (the compute backend). FIELD_EQUATION programs evaluate the analytic
// field (field_equation.glsl) in place of the texture, FIELD_SPARSE programs
// sample a sparse grid (field_sparse.glsl).

#include "field_equation.glsl"
#include "field_expression.glsl"

// The particle fieldAt() is asked about (a field expression reads them):
// its velocity at the stage being evaluated and its age. Zero elsewhere.
vec3 gParticleVelocity = vec3(0.0);
float gParticleAge = 0.0;

// Trilinear interpolation between grid points, read without the sampler's
// filter (whose weights have only 8 fractional bits on most GPUs): the cell
// of field-local point p, where p lies in it, and the corners' offsets.
struct Cell {
  ivec3 i0, i1;
  vec3 f;
};

Cell fieldCell(vec3 p) {
  ivec3 dims = sim.fieldDims.xyz;
  precise vec3 u = clamp((p - sim.fieldMin.xyz) * sim.fieldIndexScale.xyz, vec3(0.0), vec3(dims - 1));
  Cell c;
  c.i0 = min(ivec3(floor(u)), max(dims - 2, ivec3(0)));
  c.i1 = min(c.i0 + 1, dims - 1);
  precise vec3 f = u - vec3(c.i0);
  c.f = f;
  return c;
}

vec3 trilinear(vec3 f, vec3 c000, vec3 c100, vec3 c010, vec3 c110, vec3 c001, vec3 c101, vec3 c011,
               vec3 c111) {
  precise vec3 c00 = c000 + (c100 - c000) * f.x;
  precise vec3 c10 = c010 + (c110 - c010) * f.x;
  precise vec3 c01 = c001 + (c101 - c001) * f.x;
  precise vec3 c11 = c011 + (c111 - c011) * f.x;
  precise vec3 c0 = c00 + (c10 - c00) * f.y;
  precise vec3 c1 = c01 + (c11 - c01) * f.y;
  precise vec3 c = c0 + (c1 - c0) * f.z;
  return c;
}

#include "field_sparse.glsl"

#ifdef FIELD_BUFFER
// The grid as GpuField's buffer holds it: eight loads of a point (on an
// H200, faster than eight texelFetch of an RGB32F texture).
vec3 fieldSample(bool next, vec3 p) {
  Cell c = fieldCell(p);
  ivec3 stride = ivec3(1, sim.fieldDims.x, sim.fieldDims.x * sim.fieldDims.y);
  int b = c.i0.x + c.i0.y * stride.y + c.i0.z * stride.z;
  ivec3 d = (c.i1 - c.i0) * stride;
  if (next)
    return trilinear(c.f, gridPointNext(b).xyz, gridPointNext(b + d.x).xyz,
                     gridPointNext(b + d.y).xyz, gridPointNext(b + d.x + d.y).xyz,
                     gridPointNext(b + d.z).xyz, gridPointNext(b + d.x + d.z).xyz,
                     gridPointNext(b + d.y + d.z).xyz, gridPointNext(b + d.x + d.y + d.z).xyz);
  return trilinear(c.f, gridPoint(b).xyz, gridPoint(b + d.x).xyz, gridPoint(b + d.y).xyz,
                   gridPoint(b + d.x + d.y).xyz, gridPoint(b + d.z).xyz,
                   gridPoint(b + d.x + d.z).xyz, gridPoint(b + d.y + d.z).xyz,
                   gridPoint(b + d.x + d.y + d.z).xyz);
}
#else
vec3 gridSample(sampler3D field, Cell c) {
  ivec3 i0 = c.i0, i1 = c.i1;
  return trilinear(c.f, texelFetch(field, ivec3(i0.x, i0.y, i0.z), 0).xyz,
                   texelFetch(field, ivec3(i1.x, i0.y, i0.z), 0).xyz,
                   texelFetch(field, ivec3(i0.x, i1.y, i0.z), 0).xyz,
                   texelFetch(field, ivec3(i1.x, i1.y, i0.z), 0).xyz,
                   texelFetch(field, ivec3(i0.x, i0.y, i1.z), 0).xyz,
                   texelFetch(field, ivec3(i1.x, i0.y, i1.z), 0).xyz,
                   texelFetch(field, ivec3(i0.x, i1.y, i1.z), 0).xyz,
                   texelFetch(field, ivec3(i1.x, i1.y, i1.z), 0).xyz);
}

vec3 fieldSample(bool next, vec3 p) {
  Cell c = fieldCell(p);
  if (next) return gridSample(uFieldNext, c);
  return gridSample(uField, c);
}
#endif

// Whether every corner of the cell fieldSample() interpolates in at p is a
// point the field has data for (its validity mask: w / alpha 1).
bool cellValid(bool next, vec3 p) {
  Cell c = fieldCell(p);
#ifdef FIELD_BUFFER
  ivec3 stride = ivec3(1, sim.fieldDims.x, sim.fieldDims.x * sim.fieldDims.y);
  int b = c.i0.x + c.i0.y * stride.y + c.i0.z * stride.z;
  ivec3 d = (c.i1 - c.i0) * stride;
  float w = 1.0;
  for (int k = 0; k < 8; ++k) {
    int at = b + ((k & 1) != 0 ? d.x : 0) + ((k & 2) != 0 ? d.y : 0) + ((k & 4) != 0 ? d.z : 0);
    w = min(w, next ? gridPointNext(at).w : gridPoint(at).w);
  }
  return w > 0.5;
#else
  float w = 1.0;
  for (int k = 0; k < 8; ++k) {
    ivec3 at = ivec3((k & 1) != 0 ? c.i1.x : c.i0.x, (k & 2) != 0 ? c.i1.y : c.i0.y,
                     (k & 4) != 0 ? c.i1.z : c.i0.z);
    w = min(w, next ? texelFetch(uFieldNext, at, 0).w : texelFetch(uField, at, 0).w);
  }
  return w > 0.5;
#endif
}

mat3 placementRotation() {
  return mat3(sim.placementRotation[0].xyz, sim.placementRotation[1].xyz, sim.placementRotation[2].xyz);
}

vec3 toLocal(vec3 room) {
  precise vec3 local = (transpose(placementRotation()) * (room - sim.placementOffset.xyz)) * sim.stepParams.w;
  return local;
}

vec3 toRoom(vec3 local) {
  precise vec3 room = sim.placementOffset.xyz + (placementRotation() * local) * sim.placementOffset.w;
  return room;
}

#include "terrain_height.glsl"
#if defined(OBSTACLES) || defined(OBSTACLE_FLOW) || defined(OBSTACLE_LIST)
#include "obstacles.glsl"
#endif

vec3 fieldAt(vec3 x) {
  if (sim.fieldDims.w == 0) {
#if defined(OBSTACLES) || defined(OBSTACLE_FLOW)
    if (sim.obstacleCount.x != 0) return flowAroundObstacles(vec3(0.0), x, sim.modes.x != kMotionForce);
#endif
    return vec3(0.0);
  }
  vec3 local = toLocal(x);
#if defined(FIELD_EXPRESSION)
  vec3 s = expressionAt(local, sim.expression.x, gParticleVelocity, gParticleAge);
#elif defined(FIELD_EQUATION)
  vec3 s = equationAt(local);  // the analytic field itself (field_equation.glsl), not its grid
#elif defined(FIELD_SPARSE)
  precise vec3 s = sparseSample(local);  // the sparse grid (field_sparse.glsl), not the overview
#else
  precise vec3 s = fieldSample(false, local);
  if (sim.fieldBlend.y != 0.0) {
    precise vec3 n = fieldSample(true, local);
    s = s + (n - s) * sim.fieldBlend.x;
  }
#endif
  precise vec3 f = sim.stepParams.y * ((placementRotation() * s) * sim.placementOffset.w);
#if defined(OBSTACLES) || defined(OBSTACLE_FLOW)
  if (sim.obstacleCount.x != 0) return flowAroundObstacles(f, x, sim.modes.x != kMotionForce);
#endif
  return f;
}

struct Slope {
  vec3 dx;
  vec3 dv;
};

#ifdef MOLECULES
// The push tool's wind (pushWind in core/sim/particle_physics.cpp).
vec3 pushWind(vec3 x) {
  precise vec3 d = x - molecule.push.xyz;
  precise float r = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  if (!(r > 0.0 && r < molecule.push.w)) return vec3(0.0);
  precise float s = molecule.pushMore.x * (1.0 - r / molecule.push.w) / r;
  precise vec3 u = d * s;
  return u;
}
#endif

Slope derivative(vec3 x, vec3 v) {
  gParticleVelocity = v;
  precise vec3 f = fieldAt(x);
#ifdef MOLECULES
  if (molecule.pushMore.y != 0.0) f = f + pushWind(x);
#endif
  Slope s;
  if (sim.modes.x == kMotionTracer) {
    s.dx = f;
    s.dv = vec3(0.0);
  } else if (sim.modes.x == kMotionForce) {
    s.dx = v;
    precise vec3 a = f + sim.gravity.xyz;
    s.dv = a;
  } else {
    s.dx = v;
    precise vec3 a = (f - v) * sim.gravity.w + sim.gravity.xyz;
    s.dv = a;
  }
  return s;
}

// Euler is the thesis's: velocity first, then position with the new velocity.
void integrate(inout vec3 x, inout vec3 v) {
  float h = sim.stepParams.x;
  bool tracer = sim.modes.x == kMotionTracer;
  Slope k1 = derivative(x, v);
  if (sim.modes.y == kEuler) {
    precise vec3 v1 = tracer ? k1.dx : v + h * k1.dv;
    precise vec3 x1 = x + h * v1;
    v = v1;
    x = x1;
    return;
  }
  precise float h2 = 0.5 * h;
  precise vec3 x2 = x + h2 * k1.dx;
  precise vec3 v2 = v + h2 * k1.dv;
  Slope k2 = derivative(x2, v2);
  precise vec3 dx, dv;
  if (sim.modes.y == kRK2) {
    dx = k2.dx;
    dv = k2.dv;
  } else {
    precise vec3 x3 = x + h2 * k2.dx;
    precise vec3 v3 = v + h2 * k2.dv;
    Slope k3 = derivative(x3, v3);
    precise vec3 x4 = x + h * k3.dx;
    precise vec3 v4 = v + h * k3.dv;
    Slope k4 = derivative(x4, v4);
    dx = (k1.dx + 2.0 * k2.dx + 2.0 * k3.dx + k4.dx) * (1.0 / 6.0);
    dv = (k1.dv + 2.0 * k2.dv + 2.0 * k3.dv + k4.dv) * (1.0 / 6.0);
  }
  precise vec3 xn = x + h * dx;
  precise vec3 vn = tracer ? dx : v + h * dv;
  x = xn;
  v = vn;
}

// Ages, moves and bounds a particle; false when it dies.
bool advance(inout Particle p) {
  precise float life = p.positionLife.w - sim.stepParams.x;
  if (life <= 0.0) return false;
  vec3 x = p.positionLife.xyz;
  vec3 v = p.velocityKind.xyz;
  precise float age = p.velocityKind.w - p.positionLife.w;  // lived, before this step
  gParticleAge = age;
  integrate(x, v);

  if (sim.fieldDims.w != 0) {
    vec3 bmin = sim.domainMin.xyz, bmax = sim.domainMax.xyz;
    vec3 local = toLocal(x);
    if (any(lessThan(local, bmin)) || any(greaterThan(local, bmax))) {
      if (sim.modes.z == kBoundaryKill) return false;
      if (sim.modes.z == kBoundaryClamp) {
        x = toRoom(clamp(local, bmin, bmax));
      } else {
        precise vec3 wrapped = local;
        for (int a = 0; a < 3; ++a) {
          precise float e = bmax[a] - bmin[a];
          precise float r = local[a] - bmin[a];
          if (e < 1e30) wrapped[a] = bmin[a] + (r - e * floor(r / e));
        }
        x = toRoom(wrapped);
      }
    }
  }
  // Cells the field has no data for (its validity mask) are outside too:
  // killed, or held where they were (clamp); wrapping has nowhere to go.
  if (sim.fieldDims.w != 0 && sim.fieldBlend.z != 0.0) {
    vec3 local = toLocal(x);
    if (!cellValid(false, local) || (sim.fieldBlend.y != 0.0 && !cellValid(true, local))) {
      if (sim.modes.z != kBoundaryClamp) return false;
      x = p.positionLife.xyz;
      v = vec3(0.0);
    }
  }
  bool ground = sim.modes.w != 0 && sim.terrainDims.z != 0;
  if (ground) {
    float height = terrainHeight(x.xy);
    if (x.z < height) {
      x.z = height;
      if (v.z < 0.0) {
        precise float bounced = -v.z * sim.stepParams.z;
        v.z = bounced;
      }
    }
  }
  // Out of the obstacles, in order (after the ground, which they stand on).
#ifdef OBSTACLES
  if (sim.obstacleCount.x != 0) keepOutOfObstacles(x, v, ground);
#endif
  p.positionLife = vec4(x, life);
  p.velocityKind = vec4(v, p.velocityKind.w);
  return true;
}
