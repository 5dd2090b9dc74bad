#version 450 core
// GpuFluidSolver's cell passes (uPass):
//   0 stencil: each fluid cell's free faces with a fluid cell beyond (bits)
//     and its pressure stencil's centre (FluidSolver::classify);
//   1 divergence;
//   2 relax: cells of colour uColour, one red-black over-relaxation sweep;
//   3 points: each cell's velocity (the mean of its faces) into the field's
//     layout (vec4 a point, w 1), plus the subgrid eddies (I |u| times the
//     eddy pattern); a solid cell under a fluid one has that one's
//     horizontal velocity, other solid cells 0;
//   4 vorticity: curl u from the cells' velocities (central differences,
//     one-sided at the domain's edges) and its length;
//   5 confinement: epsilon h (N x w), N = grad|w| / |grad|w|| (0 in solids).
// (FluidSolver::confineVorticity's first two loops.)
#include "fluid_common.glsl"
#include "gradient_noise.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 11) writeonly restrict buffer Points { vec4 points[]; };
layout(location = 1) uniform int uPass;
layout(location = 2) uniform int uColour;

// The neighbours of c along `axis`, clamped to the grid, and 1 / their distance.
void across(ivec3 c, int axis, out ivec3 lo, out ivec3 hi, out float inverseSpan) {
  lo = c;
  hi = c;
  lo[axis] = max(c[axis] - 1, 0);
  hi[axis] = min(c[axis] + 1, fluid.dims[axis] - 1);
  inverseSpan = 1.0 / (float(hi[axis] - lo[axis]) * fluid.spacing[axis]);
}

// The subgrid eddies' pattern at x (core/solver/fluid_solver.h eddyPattern:
// seed 11, drift (0.6, 0.4, 0.7) noise cells a second).
vec3 eddyPattern(vec3 x) {
  vec3 q = x / fluid.eddies.y + fluid.eddies.z * vec3(0.6, 0.4, 0.7);
  vec3 g1 = noiseValueAndGradient(33u, q).xyz;
  vec3 g2 = noiseValueAndGradient(34u, q).xyz;
  vec3 g3 = noiseValueAndGradient(35u, q).xyz;
  return vec3(g3.y - g2.z, g1.z - g3.x, g2.x - g1.y);
}

void main() {
  ivec3 c;
  if (!gridPoint(gl_GlobalInvocationID.x, fluid.dims.xyz, c)) return;
  uint at = cellIndex(c);
  bool solid = solidVelocity[at].w != 0.0;
  if (uPass == 0) {
    uint bits = 0u;
    float diag = 0.0;
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        ivec3 face = c + (side == 1 ? unitAxis(axis) : ivec3(0));
        float given;
        if (fixedFace(axis, face, given)) continue;
        diag += fluid.inverse2[axis];
        int beyond = c[axis] + (side == 1 ? 1 : -1);
        if (beyond >= 0 && beyond < fluid.dims[axis]) bits |= 1u << uint(2 * axis + side);
      }
    stencilBits[at] = solid ? 0u : bits;
    diagonal[at] = solid ? 0.0 : diag;
  } else if (uPass == 1) {
    if (solid) {
      divergence[at] = 0.0;
      return;
    }
    float div = (faceU[faceIndex(0, c + ivec3(1, 0, 0))] - faceU[faceIndex(0, c)]) * fluid.inverse.x +
                (faceV[faceIndex(1, c + ivec3(0, 1, 0))] - faceV[faceIndex(1, c)]) * fluid.inverse.y +
                (faceW[faceIndex(2, c + ivec3(0, 0, 1))] - faceW[faceIndex(2, c)]) * fluid.inverse.z;
    divergence[at] = div;
  } else if (uPass == 2) {
    if (((c.x + c.y + c.z) & 1) != uColour) return;
    float diag = diagonal[at];
    if (diag == 0.0) return;
    uint bits = stencilBits[at];
    int stride[3] = int[](1, fluid.dims.x, fluid.dims.x * fluid.dims.y);
    float sum = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
      if ((bits & (1u << uint(2 * axis))) != 0u) sum += pressure[int(at) - stride[axis]] * fluid.inverse2[axis];
      if ((bits & (1u << uint(2 * axis + 1))) != 0u) sum += pressure[int(at) + stride[axis]] * fluid.inverse2[axis];
    }
    float p = pressure[at];
    pressure[at] = p + fluid.minimum.w * ((sum - divergence[at]) / diag - p);
  } else if (uPass == 4) {
    vec3 d[3];
    for (int axis = 0; axis < 3; ++axis) {
      ivec3 lo, hi;
      float inverseSpan;
      across(c, axis, lo, hi, inverseSpan);
      d[axis] = (cellVelocity(hi) - cellVelocity(lo)) * inverseSpan;
    }
    vec3 w = vec3(d[1].z - d[2].y, d[2].x - d[0].z, d[0].y - d[1].x);
    vorticity[at] = vec4(w, length(w));
  } else if (uPass == 5) {
    confinement[at] = vec4(0.0);
    if (solid) return;
    vec3 eta;
    for (int axis = 0; axis < 3; ++axis) {
      ivec3 lo, hi;
      float inverseSpan;
      across(c, axis, lo, hi, inverseSpan);
      eta[axis] = (vorticity[cellIndex(hi)].w - vorticity[cellIndex(lo)].w) * inverseSpan;
    }
    float len = length(eta);
    if (!(len > 1e-20)) return;
    confinement[at] = vec4(fluid.viscosity.y * cross(eta / len, vorticity[at].xyz), 0.0);
  } else {
    // A solid cell under a fluid one takes its horizontal velocity (the free-slip ground's).
    ivec3 above = c + ivec3(0, 0, 1);
    bool ground = solid && above.z < fluid.dims.z && !solidCell(above);
    vec3 v = cellVelocity(ground ? above : c);
    if (fluid.eddies.x > 0.0) {
      vec3 x = fluid.minimum.xyz + vec3(c) * fluid.spacing.xyz;
      v += (fluid.eddies.x * length(v)) * eddyPattern(x);
    }
    if (ground) v.z = 0.0;
    points[at] = vec4(v, 1.0);
  }
}
