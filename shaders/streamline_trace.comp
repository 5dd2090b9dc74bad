#version 450 core
// StreamlineRenderer, tracing: one invocation per seed and direction traces
// the streamline in arc length (dx/ds = f / |f|) with the simulation's
// integrator, as traceStreamlines (core/flow/streamline_tracer.cpp) does on the
// CPU: same samples (fieldAt, particle_physics.glsl), same steps, same stops.
// Line l = 2 * seed + direction (0 backward, 1 forward); its point 0 is the seed.
#include "sim_block.glsl"
#include "particle_physics.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 3) readonly restrict buffer Seeds { vec4 seeds[]; };
layout(std430, binding = 4) writeonly restrict buffer Points { vec4 points[]; };  // [line][k]: position, velocity
layout(std430, binding = 5) writeonly restrict buffer Counts { uint counts[]; };

layout(location = 0) uniform uint uLines;
layout(location = 1) uniform int uSteps;
layout(location = 2) uniform float uStep;

const float kStill = 1e-6;

bool inside(vec3 x) {
  vec3 local = toLocal(x);
  if (any(lessThan(local, sim.domainMin.xyz)) || any(greaterThan(local, sim.domainMax.xyz))) return false;
  if (sim.fieldBlend.z == 0.0) return true;
  return cellValid(false, local) && (sim.fieldBlend.y == 0.0 || cellValid(true, local));
}

bool direction(vec3 x, float sign, out vec3 d) {
  precise vec3 f = fieldAt(x);
  float speed = length(f);
  d = vec3(0.0);
  if (!(speed >= kStill)) return false;
  precise vec3 unit = f * (sign / speed);
  d = unit;
  return true;
}

bool advanceOne(inout vec3 x, float h, float sign) {
  vec3 k1, k2, k3, k4;
  if (!direction(x, sign, k1)) return false;
  if (sim.modes.y == kEuler) {
    precise vec3 e = x + h * k1;
    x = e;
    return true;
  }
  precise float h2 = 0.5 * h;
  precise vec3 x2 = x + h2 * k1;
  if (!direction(x2, sign, k2)) return false;
  if (sim.modes.y == kRK2) {
    precise vec3 m = x + h * k2;
    x = m;
    return true;
  }
  precise vec3 x3 = x + h2 * k2;
  if (!direction(x3, sign, k3)) return false;
  precise vec3 x4 = x + h * k3;
  if (!direction(x4, sign, k4)) return false;
  precise vec3 slope = (k1 + 2.0 * k2 + 2.0 * k3 + k4) * (1.0 / 6.0);
  precise vec3 r = x + h * slope;
  x = r;
  return true;
}

void main() {
  uint line = gl_GlobalInvocationID.x;
  if (line >= uLines) return;
  vec3 x = seeds[line / 2u].xyz;
  float sign = (line & 1u) != 0u ? 1.0 : -1.0;
  uint base = line * uint(uSteps + 1) * 2u;
  if (sim.fieldDims.w == 0 || !inside(x)) {
    counts[line] = 0u;
    return;
  }
  points[base] = vec4(x, 1.0);
  points[base + 1u] = vec4(fieldAt(x), 0.0);
  uint n = 1u;
  for (int s = 0; s < uSteps; ++s) {
    if (!advanceOne(x, uStep, sign) || !inside(x)) break;
    points[base + 2u * n] = vec4(x, 1.0);
    points[base + 2u * n + 1u] = vec4(fieldAt(x), 0.0);
    ++n;
  }
  counts[line] = n;
}
