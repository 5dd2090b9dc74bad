#version 450 core
// ParticleSplat, step 1: one invocation turns the backend's live count (on the
// GPU: ParticleBackend::records()) into the splat passes' dispatch sizes: one
// invocation a particle (atomic variant), or at most kSplatMaxBinGroups
// workgroups of `perGroup` particles each (the tiled variant's binning).
#include "splat_common.glsl"

layout(local_size_x = 1) in;
layout(std430, binding = 4) readonly buffer Counts { uint counts[]; };
layout(std430, binding = 5) writeonly buffer Dispatch {
  uvec4 dispatch;  // x, y, z, (unused)
  uint count;
  uvec4 binDispatch;
  uint perGroup;
} args;
layout(location = 0) uniform uint uCountIndex;
layout(location = 1) uniform uint uCountAdd;

const uint kGroupsPerRow = 32768u;

void main() {
  uint count = counts[uCountIndex] + uCountAdd;
  uint groups = (count + 255u) / 256u;
  args.dispatch = uvec4(min(groups, kGroupsPerRow), (groups + kGroupsPerRow - 1u) / kGroupsPerRow, 1u, 0u);
  args.count = count;
  // Binning workgroups: enough particles each that clearing and flushing a
  // histogram of every tile is small beside them.
  uint perGroup = max(2048u, ((count + kSplatMaxBinGroups - 1u) / kSplatMaxBinGroups + 255u) / 256u * 256u);
  args.binDispatch = uvec4((count + perGroup - 1u) / perGroup, 1u, 1u, 0u);
  args.perGroup = perGroup;
}
