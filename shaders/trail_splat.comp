#version 450 core
// ParticleSplat, trails: each trail segment (as trail.vert joins them) walked
// pixel by pixel in the view and added to the splat sums like a splat's
// pixels (splat_common.glsl's channels): alpha fading along the trail and
// behind the scene, the particle's colour coordinate, the normal towards the
// eye. Integer sums, so the order the segments arrive in does not matter.
#include "view_block.glsl"
#include "render_block.glsl"
#include "splat_common.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 1) readonly restrict buffer VelocityKind { vec4 velocityKind[]; };
layout(std430, binding = 6) restrict buffer SplatAccumulation { uint accum[]; };
layout(std430, binding = 7) readonly restrict buffer Ring { vec4 ring[]; };
layout(std430, binding = 13) readonly restrict buffer Dispatch { uvec4 dispatch; };
layout(binding = 3) uniform sampler2D uSceneDepth;
layout(location = 0) uniform int uLength;
layout(location = 1) uniform int uHead;

const int kMaxPixels = 64;  // a segment's pixels (one frame of motion: a few)

void main() {
  uint g = (gl_WorkGroupID.y * dispatch.x + gl_WorkGroupID.x) * 256u + gl_LocalInvocationIndex;
  uint segments = uint(uLength - 1);
  uint o = g / segments;
  int j = int(g % segments);
  if (o >= dispatch.w) return;
  int newer = (uHead - j + uLength) % uLength, older = (uHead - j - 1 + uLength) % uLength;
  vec4 a = ring[o * uint(uLength) + uint(newer)], b = ring[o * uint(uLength) + uint(older)];
  if (a.w < 0.5 || b.w < 0.5) return;
  vec4 ca = view.viewProjection * vec4(a.xyz, 1.0), cb = view.viewProjection * vec4(b.xyz, 1.0);
  if (ca.w <= 1e-4 || cb.w <= 1e-4) return;
  vec2 size = view.viewport.zw;
  vec2 pa = (ca.xy / ca.w * 0.5 + 0.5) * size, pb = (cb.xy / cb.w * 0.5 + 0.5) * size;
  vec4 pl = positionLife[o], vk = velocityKind[o];
  float age = clamp(1.0 - pl.w / max(vk.w, 1e-6), 0.0, 1.0);
  float t = colorCoordinate(age, vk.xyz, pl.xyz);
  float opacity = mix(look.colorBirth.a, look.colorDeath.a, age);
  vec3 toEye = normalize(view.eye.xyz - a.xyz);
  ivec3 nn0 = ivec3(round(toEye * kSplatScale));
  vec2 d = pb - pa;
  int n = min(int(ceil(max(abs(d.x), abs(d.y)))), kMaxPixels);
  uint width = uint(size.x);
  for (int s = 0; s < n; ++s) {  // the pixel at the older end belongs to the next segment
    float u = (float(s) + 0.5) / float(max(n, 1));
    ivec2 p = ivec2(floor(pa + u * d));
    if (p.x < 0 || p.y < 0 || p.x >= int(size.x) || p.y >= int(size.y)) continue;
    float distance = mix(ca.w, cb.w, u);
    float scene = viewDistance(texelFetch(uSceneDepth, p, 0).r);
    float fade = clamp((scene - distance) / max(look.params.y, 1e-4), 0.0, 1.0);
    float along = (float(j) + u) / float(segments);
    float alpha = opacity * (1.0 - along) * fade;
    if (alpha < 1.0 / 512.0) continue;
    uint base = (uint(p.y) * width + uint(p.x)) * kSplatStride;
    float opticalDepth = -log(1.0 - min(alpha, 0.999));
#ifdef SHADOWS
    float weight = opticalDepth;  // splat_common.glsl; trails are not shadowed (light 1)
#else
    float weight = alpha;
#endif
    atomicAdd(accum[base + 0u], uint(weight * kSplatScale + 0.5));
    atomicAdd(accum[base + 1u], uint(weight * t * kSplatScale + 0.5));
    atomicAdd(accum[base + 2u], uint(opticalDepth * kSplatScale + 0.5));
    atomicAdd(accum[base + 3u], uint(int(round(weight * float(nn0.x)))));
    atomicAdd(accum[base + 4u], uint(int(round(weight * float(nn0.y)))));
    atomicAdd(accum[base + 5u], uint(int(round(weight * float(nn0.z)))));
  }
}
