#version 450 core
// StreamlineRenderer, tracing: one invocation per seed and direction traces
// the streamline in arc length (dx/ds = f / |f|) with the streamlines' own
// integrator (fixed Euler, RK2, RK4, or adaptive RK45), as traceStreamlines
// (core/flow/streamline_tracer.cpp) does on the CPU: same samples (fieldAt,
// particle_physics.glsl), same steps, same stops, the same Cash-Karp
// coefficients (uCashKarp, from core/flow/cash_karp.h).
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
layout(location = 3) uniform int uIntegrator;  // StreamIntegrator: 0 Euler, 1 RK2, 2 RK4, 3 RK45
layout(location = 4) uniform float uTolerance; // m, RK45
layout(location = 5) uniform float uLength;    // m, RK45 stops here
layout(location = 6) uniform float uCashKarp[24];

const int kStreamEuler = 0, kStreamRK2 = 1, kStreamRK45 = 3;
// Positions in uCashKarp (cash_karp.h).
const int A21 = 0, A31 = 1, A32 = 2, A41 = 3, A42 = 4, A43 = 5, A51 = 6, A52 = 7, A53 = 8,
          A54 = 9, A61 = 10, A62 = 11, A63 = 12, A64 = 13, A65 = 14, B1 = 15, B3 = 16, B4 = 17,
          B6 = 18, E1 = 19, E3 = 20, E4 = 21, E5 = 22, E6 = 23;

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
  if (uIntegrator == kStreamEuler) {
    precise vec3 e = x + h * k1;
    x = e;
    return true;
  }
  precise float h2 = 0.5 * h;
  precise vec3 x2 = x + h2 * k1;
  if (!direction(x2, sign, k2)) return false;
  if (uIntegrator == kStreamRK2) {
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

const int kTrialAccepted = 0, kTrialRejected = 1, kTrialStill = 2;

// One try of an RK45 step of h from x (rk45Step in streamline_tracer.cpp).
int rk45Step(inout vec3 x, float h, float sign, bool shortest, out bool small) {
  small = false;
  vec3 k1, k2, k3, k4, k5, k6;
  if (!direction(x, sign, k1)) return kTrialStill;
  precise vec3 x2 = x + h * (uCashKarp[A21] * k1);
  if (!direction(x2, sign, k2)) return kTrialStill;
  precise vec3 x3 = x + h * (uCashKarp[A31] * k1 + uCashKarp[A32] * k2);
  if (!direction(x3, sign, k3)) return kTrialStill;
  precise vec3 x4 = x + h * (uCashKarp[A41] * k1 + uCashKarp[A42] * k2 + uCashKarp[A43] * k3);
  if (!direction(x4, sign, k4)) return kTrialStill;
  precise vec3 x5 = x + h * (uCashKarp[A51] * k1 + uCashKarp[A52] * k2 + uCashKarp[A53] * k3 +
                             uCashKarp[A54] * k4);
  if (!direction(x5, sign, k5)) return kTrialStill;
  precise vec3 x6 = x + h * (uCashKarp[A61] * k1 + uCashKarp[A62] * k2 + uCashKarp[A63] * k3 +
                             uCashKarp[A64] * k4 + uCashKarp[A65] * k5);
  if (!direction(x6, sign, k6)) return kTrialStill;
  precise vec3 error = h * (uCashKarp[E1] * k1 + uCashKarp[E3] * k3 + uCashKarp[E4] * k4 +
                            uCashKarp[E5] * k5 + uCashKarp[E6] * k6);
  precise float error2 = dot(error, error);
  precise float tolerance2 = uTolerance * uTolerance;
  precise float turn = dot(k1, k6);
  bool turns = turn < 0.875;  // more than about 29 degrees in one step (streamline_tracer.cpp)
  if ((error2 > tolerance2 || turns) && !shortest) return kTrialRejected;
  precise float scaled = error2 * 1024.0;
  small = scaled < tolerance2;
  precise vec3 r = x + h * (uCashKarp[B1] * k1 + uCashKarp[B3] * k3 + uCashKarp[B4] * k4 +
                            uCashKarp[B6] * k6);
  x = r;
  return kTrialAccepted;
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
  if (uIntegrator != kStreamRK45) {
    for (int s = 0; s < uSteps; ++s) {
      if (!advanceOne(x, uStep, sign) || !inside(x)) break;
      points[base + 2u * n] = vec4(x, 1.0);
      points[base + 2u * n + 1u] = vec4(fieldAt(x), 0.0);
      ++n;
    }
  } else {
    // Steps between uStep / 64 and uStep, halved and doubled.
    float longest = uStep;
    precise float shortest = uStep * (1.0 / 64.0);
    float h = longest;
    precise float travelled = 0.0;
    while (int(n) - 1 < uSteps && travelled < uLength) {
      precise float left = uLength - travelled;
      float tried = min(h, left);
      bool small;
      vec3 next = x;
      int t = rk45Step(next, tried, sign, tried <= shortest, small);
      bool outside = t == kTrialAccepted && !inside(next);
      if (t == kTrialRejected || ((t == kTrialStill || outside) && tried > shortest)) {
        precise float halved = 0.5 * tried;
        h = max(halved, shortest);
        continue;
      }
      if (t == kTrialStill || outside) break;
      x = next;
      travelled += tried;
      points[base + 2u * n] = vec4(x, 1.0);
      points[base + 2u * n + 1u] = vec4(fieldAt(x), 0.0);
      ++n;
      if (small) {
        precise float twice = 2.0 * h;
        h = min(twice, longest);
      }
    }
  }
  counts[line] = n;
}
