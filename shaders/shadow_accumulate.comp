#version 450 core
// OpacityShadowMap, step 4: for each cell across the light, the optical depth
// from the light down to each layer boundary (a running sum of the layers'
// sums), into the map shadow_block.glsl samples; zeroes the sums for the
// next frame.
layout(local_size_x = 16, local_size_y = 16) in;
layout(std430, binding = 16) restrict buffer Layers { uint layerSums[]; };
layout(r32f, binding = 0) writeonly uniform image3D uDepth;
layout(location = 0) uniform int uSide;
layout(location = 1) uniform int uLayers;

const float kScale = 4096.0;  // shadow_splat.comp's

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= uSide || p.y >= uSide) return;
  uint sum = 0u;
  imageStore(uDepth, ivec3(p, 0), vec4(0.0));
  for (int layer = 0; layer < uLayers; ++layer) {
    uint at = uint((layer * uSide + p.y) * uSide + p.x);
    sum += layerSums[at];
    layerSums[at] = 0u;
    imageStore(uDepth, ivec3(p, layer + 1), vec4(float(sum) / kScale));
  }
}
