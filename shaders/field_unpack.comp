#version 450 core
// GpuField: whole z layers of a float grid, staged in a buffer as three floats
// a point (x fastest), or four with the validity mask in w, written into the
// grid's RGBA32F 3D texture (w 1 where the grid has no mask). NVIDIA's driver
// unpacked an RGB32F texture from a buffer at 1.3-2.7 GB/s; this copy runs at
// the GPU's bandwidth. The texels hold the staged bits unchanged.

layout(local_size_x = 256) in;

layout(std430, binding = 0) readonly restrict buffer Staged { float staged[]; };
layout(rgba32f, binding = 0) writeonly restrict uniform image3D uGrid;

layout(location = 0) uniform uvec2 uLayerSize;  // the grid's x and y points
layout(location = 1) uniform uint uFirstLayer;  // the texture's z of the first staged layer
layout(location = 2) uniform uint uPoints;      // staged points this dispatch
layout(location = 3) uniform uint uComponents;  // 3, or 4 with the mask
layout(location = 4) uniform uint uSkip;        // floats before the first point in the binding

void main() {
  uint stride = gl_NumWorkGroups.x * 256u;
  uint layer = uLayerSize.x * uLayerSize.y;
  for (uint i = gl_GlobalInvocationID.x; i < uPoints; i += stride) {
    uint at = uSkip + i * uComponents;
    vec4 v = vec4(staged[at], staged[at + 1u], staged[at + 2u],
                  uComponents == 4u ? staged[at + 3u] : 1.0);
    uint z = i / layer, inLayer = i - z * layer;
    uint y = inLayer / uLayerSize.x, x = inLayer - y * uLayerSize.x;
    imageStore(uGrid, ivec3(x, y, uFirstLayer + z), v);
  }
}
