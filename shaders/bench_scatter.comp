#version 450 core
// sandstorm-bench: spreads N records over clip space (x, y in [-1, 1], z in
// [0, 1)) with an integer hash, for the point-draw ceiling.
layout(local_size_x = 256) in;
layout(std430, binding = 0) writeonly buffer Records { vec4 records[]; };
layout(location = 0) uniform uint uCount;

uint hash(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

void main() {
  uint i = gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 256u + gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  uint a = hash(i), b = hash(a), c = hash(b);
  records[i] = vec4(vec3(a >> 8, b >> 8, c >> 8) * (1.0 / 16777216.0) * vec3(2.0, 2.0, 1.0) - vec3(1.0, 1.0, 0.0), 1.0);
}
