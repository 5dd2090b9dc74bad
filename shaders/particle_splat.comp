#version 450 core
// ParticleSplat, step 2: each invocation splats one particle into the pixels
// its billboard would cover (ParticleRender's spherical billboard: same size,
// sprite, normal, colour, soft depth test against the scene), accumulating
// order-independent sums (splat_common.glsl) for the resolve.
#include "view_block.glsl"
#include "render_block.glsl"
#include "splat_common.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 1) readonly restrict buffer VelocityKind { vec4 velocityKind[]; };
layout(std430, binding = 5) readonly buffer Dispatch {
  uvec4 dispatch;
  uint count;
} args;
layout(binding = 2) uniform sampler2D uSprite;      // R8 puff, as ParticleRender's
layout(binding = 3) uniform sampler2D uSceneDepth;  // the scene's depth, this view's size

const float kMaxRadius = 16.0;  // pixels: larger particles are drawn this large (use billboards for them)

void main() {
  uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 256u + gl_LocalInvocationIndex;
  if (i >= args.count) return;
  vec4 pl = positionLife[i];
  vec4 vk = velocityKind[i];
  vec3 center = pl.xyz;
  float age = clamp(1.0 - pl.w / max(vk.w, 1e-6), 0.0, 1.0);

  vec4 clip = view.viewProjection * vec4(center, 1.0);
  if (clip.w <= 1e-4) return;
  vec2 size = view.viewport.zw;
  vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * size;  // window coordinates of the centre
  float radius = 0.5 * look.params.x;
  vec2 radiusPx = min(radius * vec2(view.projection[0][0], view.projection[1][1]) * 0.5 * size / clip.w,
                      vec2(kMaxRadius));
  if (pixel.x + radiusPx.x < 0.0 || pixel.y + radiusPx.y < 0.0 || pixel.x - radiusPx.x > size.x ||
      pixel.y - radiusPx.y > size.y)
    return;

  // The billboard's frame, as particle_render.geom builds it.
  vec3 toEye = view.eye.xyz - center;
  float distance = length(toEye);
  if (distance < 1e-4) return;
  vec3 n = toEye / distance;
  vec3 worldUp = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
  vec3 right = normalize(cross(worldUp, n));
  vec3 up = cross(n, right);

  float particleDistance = clip.w;  // camera-space distance of the centre
  float opacity = mix(look.colorBirth.a, look.colorDeath.a, age);
  ivec2 lo = max(ivec2(floor(pixel - radiusPx)), ivec2(0));
  ivec2 hi = min(ivec2(ceil(pixel + radiusPx)), ivec2(size) - 1);
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      vec2 corner = (vec2(x, y) + 0.5 - pixel) / radiusPx;
      float r2 = dot(corner, corner);
      if (r2 > 1.0) continue;
      float shape = textureLod(uSprite, 0.5 * corner + 0.5, 0.0).r;
      float sceneDistance = viewDistance(texelFetch(uSceneDepth, ivec2(x, y), 0).r);
      float fade = clamp((sceneDistance - particleDistance) / max(look.params.y, 1e-4), 0.0, 1.0);
      float alpha = opacity * shape * fade;
      if (alpha < 1.0 / 512.0) continue;
      vec3 normal = normalize(corner.x * right + corner.y * up + sqrt(1.0 - r2) * n);
      uint base = (uint(y) * uint(size.x) + uint(x)) * kSplatStride;
      atomicAdd(accum[base + 0u], uint(alpha * kSplatScale + 0.5));
      atomicAdd(accum[base + 1u], uint(alpha * age * kSplatScale + 0.5));
      atomicAdd(accum[base + 2u], uint(-log(1.0 - min(alpha, 0.999)) * kSplatScale + 0.5));
      ivec3 nn = ivec3(round(alpha * normal * kSplatScale));
      atomicAdd(accum[base + 3u], uint(nn.x));
      atomicAdd(accum[base + 4u], uint(nn.y));
      atomicAdd(accum[base + 5u], uint(nn.z));
    }
}
