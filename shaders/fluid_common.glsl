// The live flow solver on the GPU (GpuFluidSolver): its block, its buffers,
// and the grid's rules, the twins of core/solver/fluid_solver.cpp's (a MAC
// grid: cells on the field's points, u on x-faces, v on y-faces, w on z-faces).
layout(std140, binding = 6) uniform FluidBlock {
  ivec4 dims;      // cells nx, ny, nz
  vec4 spacing;    // hx, hy, hz, dt
  vec4 inverse;    // 1 / h
  vec4 inverse2;   // 1 / h^2
  vec4 minimum;    // the first cell's centre, w: over-relaxation
  ivec4 lowSide;   // per axis: 0 open, 1 wall, 2 inflow (the low side)
  ivec4 highSide;  // ... the high side
  vec4 wind;       // m/s, the inflow's velocity
  vec4 rotor;      // centre xyz, w: radius
  vec4 rotorMore;  // x: acceleration (m/s^2, down), y: half the disc's thickness
  vec4 viscosity;  // x: nu * dt of one diffusion substep, y: vorticity confinement's epsilon * h
  vec4 eddies;     // subgrid eddies: x intensity, y size (m), z the solver's time (s)
} fluid;

layout(std430, binding = 0) restrict buffer FaceU { float faceU[]; };
layout(std430, binding = 1) restrict buffer FaceV { float faceV[]; };
layout(std430, binding = 2) restrict buffer FaceW { float faceW[]; };
layout(std430, binding = 3) restrict buffer OutU { float outU[]; };
layout(std430, binding = 4) restrict buffer OutV { float outV[]; };
layout(std430, binding = 5) restrict buffer OutW { float outW[]; };
layout(std430, binding = 6) restrict buffer Pressure { float pressure[]; };
layout(std430, binding = 7) restrict buffer Divergence { float divergence[]; };
layout(std430, binding = 8) readonly restrict buffer Solid { vec4 solidVelocity[]; };  // w: 1 solid
layout(std430, binding = 9) restrict buffer Stencil { uint stencilBits[]; };  // bit 2a+s; 64: solid
layout(std430, binding = 10) restrict buffer Diagonal { float diagonal[]; };
layout(std430, binding = 12) restrict buffer Vorticity { vec4 vorticity[]; };  // curl u, |curl u|
layout(std430, binding = 13) restrict buffer Confinement { vec4 confinement[]; };  // the force

const int kSideOpen = 0, kSideWall = 1, kSideInflow = 2;

ivec3 unitAxis(int axis) {
  return ivec3(axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, axis == 2 ? 1 : 0);
}

ivec3 faceDims(int axis) {
  return fluid.dims.xyz + unitAxis(axis);
}

uint cellIndex(ivec3 c) {
  return uint(c.x + fluid.dims.x * (c.y + fluid.dims.y * c.z));
}

uint faceIndex(int axis, ivec3 f) {
  ivec3 d = faceDims(axis);
  return uint(f.x + d.x * (f.y + d.y * f.z));
}

float readFace(int axis, uint i) {
  return axis == 0 ? faceU[i] : axis == 1 ? faceV[i] : faceW[i];
}

void writeFace(int axis, uint i, float value) {
  if (axis == 0) faceU[i] = value;
  else if (axis == 1) faceV[i] = value;
  else faceW[i] = value;
}

bool solidCell(ivec3 c) {
  return solidVelocity[cellIndex(c)].w != 0.0;
}

// Whether face f on `axis` (the low side of cell f) is given, and its velocity (fixedFace).
bool fixedFace(int axis, ivec3 f, out float velocity) {
  velocity = 0.0;
  int along = f[axis];
  if (along == 0 || along == fluid.dims[axis]) {
    int side = along == 0 ? fluid.lowSide[axis] : fluid.highSide[axis];
    if (side == kSideOpen) return false;
    velocity = side == kSideInflow ? fluid.wind[axis] : 0.0;
    return true;
  }
  ivec3 lo = f - unitAxis(axis);
  vec4 a = solidVelocity[cellIndex(lo)], b = solidVelocity[cellIndex(f)];
  if (a.w == 0.0 && b.w == 0.0) return false;
  velocity = a.w != 0.0 ? a[axis] : b[axis];
  return true;
}

// The velocity at cell c's centre (the mean of its faces), 0 in a solid cell.
vec3 cellVelocity(ivec3 c) {
  if (solidCell(c)) return vec3(0.0);
  return 0.5 * vec3(faceU[faceIndex(0, c)] + faceU[faceIndex(0, c + ivec3(1, 0, 0))],
                    faceV[faceIndex(1, c)] + faceV[faceIndex(1, c + ivec3(0, 1, 0))],
                    faceW[faceIndex(2, c)] + faceW[faceIndex(2, c + ivec3(0, 0, 1))]);
}

// Trilinear sample of the faces on `axis` at room point p (sampleFaces).
float sampleFaces(int axis, vec3 p) {
  ivec3 d = faceDims(axis);
  vec3 q = (p - fluid.minimum.xyz) * fluid.inverse.xyz;
  q[axis] += 0.5;
  q = clamp(q, vec3(0.0), vec3(d - 1));
  ivec3 i0 = min(ivec3(floor(q)), d - 2);
  vec3 f = q - vec3(i0);
  float c000 = readFace(axis, faceIndex(axis, i0));
  float c100 = readFace(axis, faceIndex(axis, i0 + ivec3(1, 0, 0)));
  float c010 = readFace(axis, faceIndex(axis, i0 + ivec3(0, 1, 0)));
  float c110 = readFace(axis, faceIndex(axis, i0 + ivec3(1, 1, 0)));
  float c001 = readFace(axis, faceIndex(axis, i0 + ivec3(0, 0, 1)));
  float c101 = readFace(axis, faceIndex(axis, i0 + ivec3(1, 0, 1)));
  float c011 = readFace(axis, faceIndex(axis, i0 + ivec3(0, 1, 1)));
  float c111 = readFace(axis, faceIndex(axis, i0 + ivec3(1, 1, 1)));
  float c00 = c000 + (c100 - c000) * f.x, c10 = c010 + (c110 - c010) * f.x;
  float c01 = c001 + (c101 - c001) * f.x, c11 = c011 + (c111 - c011) * f.x;
  float c0 = c00 + (c10 - c00) * f.y, c1 = c01 + (c11 - c01) * f.y;
  return c0 + (c1 - c0) * f.z;
}

// The index of invocation g in a grid of `d`, or false beyond it.
bool gridPoint(uint g, ivec3 d, out ivec3 at) {
  uint n = uint(d.x * d.y * d.z);
  if (g >= n) return false;
  at = ivec3(int(g % uint(d.x)), int((g / uint(d.x)) % uint(d.y)), int(g / uint(d.x * d.y)));
  return true;
}
