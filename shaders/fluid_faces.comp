#version 450 core
// GpuFluidSolver's face passes on the faces of axis uAxis (uPass):
//   0 fix: given faces take their velocity (walls, inflow, solid cells);
//   1 rotor: w faces in the rotor's disc lose acceleration * dt;
//   2 advect: out = the faces' velocity where the flow was dt ago (reads face*, writes out*);
//   3 diffuse: out = face + nu dt (its 7-point Laplacian, neighbours clamped);
//   4 gradient: free faces lose the pressure's gradient (0 beyond open sides);
//   5 confine: free faces between two cells gain dt times the mean of their
//     vorticity confinement forces.
// The twins of FluidSolver's setBoundaries/classify, applyForces, advect,
// diffuse and project.
#include "fluid_common.glsl"

layout(local_size_x = 256) in;
layout(location = 0) uniform int uAxis;
layout(location = 1) uniform int uPass;

void main() {
  int axis = uAxis;
  ivec3 d = faceDims(axis);
  ivec3 f;
  if (!gridPoint(gl_GlobalInvocationID.x, d, f)) return;
  uint at = faceIndex(axis, f);
  float given;
  if (uPass == 0) {
    if (fixedFace(axis, f, given)) writeFace(axis, at, given);
  } else if (uPass == 1) {
    vec3 x = fluid.minimum.xyz + (vec3(f) - vec3(0.0, 0.0, 0.5)) * fluid.spacing.xyz;
    vec2 r = x.xy - fluid.rotor.xy;
    if (dot(r, r) <= fluid.rotor.w * fluid.rotor.w && abs(x.z - fluid.rotor.z) <= fluid.rotorMore.y)
      faceW[at] -= fluid.rotorMore.x * fluid.spacing.w;
  } else if (uPass == 2) {
    vec3 velocity;
    velocity[axis] = readFace(axis, at);
    for (int o = 1; o <= 2; ++o) {
      int other = (axis + o) % 3;
      float sum = 0.0;
      for (int lo = 0; lo < 2; ++lo)
        for (int hi = 0; hi < 2; ++hi) {
          ivec3 c = f;
          c[axis] = clamp(f[axis] - 1 + lo, 0, fluid.dims[axis] - 1);
          c[other] = f[other] + hi;
          sum += readFace(other, faceIndex(other, c));
        }
      velocity[other] = 0.25 * sum;
    }
    vec3 x = fluid.minimum.xyz + vec3(f) * fluid.spacing.xyz;
    x[axis] -= 0.5 * fluid.spacing[axis];
    float value = sampleFaces(axis, x - fluid.spacing.w * velocity);
    if (axis == 0) outU[at] = value;
    else if (axis == 1) outV[at] = value;
    else outW[at] = value;
  } else if (uPass == 3) {
    float here = readFace(axis, at);
    float lap = 0.0;
    for (int a = 0; a < 3; ++a) {
      ivec3 e = unitAxis(a);
      float up = readFace(axis, faceIndex(axis, clamp(f + e, ivec3(0), d - 1)));
      float down = readFace(axis, faceIndex(axis, clamp(f - e, ivec3(0), d - 1)));
      lap += (up - 2.0 * here + down) * fluid.inverse2[a];
    }
    float value = here + fluid.viscosity.x * lap;
    if (axis == 0) outU[at] = value;
    else if (axis == 1) outV[at] = value;
    else outW[at] = value;
  } else if (uPass == 5) {
    if (f[axis] == 0 || f[axis] == fluid.dims[axis] || fixedFace(axis, f, given)) return;
    ivec3 lo = f - unitAxis(axis);
    float force = 0.5 * (confinement[cellIndex(lo)][axis] + confinement[cellIndex(f)][axis]);
    writeFace(axis, at, readFace(axis, at) + fluid.spacing.w * force);
  } else {
    if (fixedFace(axis, f, given)) return;
    ivec3 lo = f - unitAxis(axis);
    float right = f[axis] < fluid.dims[axis] ? pressure[cellIndex(f)] : 0.0;
    float left = lo[axis] >= 0 ? pressure[cellIndex(lo)] : 0.0;
    writeFace(axis, at, readFace(axis, at) - (right - left) * fluid.inverse[axis]);
  }
}
