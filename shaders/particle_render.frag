#version 450 core
// ParticleRender: writes premultiplied colour, premultiplied sphere normals and
// the premultiplied share of the light reaching it (shadows) into the
// offscreen particle buffer (blended ONE, ONE_MINUS_SRC_ALPHA, thesis
// 5.1.3), for ParticlePost to light. Particles behind the scene are hidden and
// fade out as they near it (soft particles).
#include "view_block.glsl"
#include "render_block.glsl"
#include "motion_blur.glsl"

layout(binding = 2) uniform sampler2D uSprite;      // R8 puff
layout(binding = 3) uniform sampler2D uSceneDepth;  // the scene's depth, same size as this target

#ifdef POINTS
in float vAge;
in float vColor;
in float vLight;
#else
in vec2 gCorner;
in vec2 gMotion;
in vec3 gRight;
in vec3 gUp;
in vec3 gToEye;
in float gAge;
in float gColor;
in float gLight;
#endif
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outLight;  // R16F: red only

void main() {
#ifdef POINTS
  vec2 corner = 2.0 * gl_PointCoord - 1.0;
  float age = vAge;
  float colorT = vColor;
  float light = vLight;
  float shape = dot(corner, corner) <= 1.0 ? 1.0 : 0.0;
  vec3 normal = vec3(0.0);  // points are coloured, not lit
#else
  vec2 corner = gCorner;
  float age = gAge;
  float colorT = gColor;
  float light = gLight;
  float shape;
  if (gMotion.x > 0.0) {  // motion blur
    vec2 closest;
    shape = smearedPuff(corner, gMotion, closest) * puffLumps(closest);
    corner = closest;
  }
  float r2 = dot(corner, corner);
  if (r2 > 1.0) discard;
  if (gMotion.x == 0.0) shape = texture(uSprite, 0.5 * corner + 0.5).r;
  vec3 normal = normalize(corner.x * gRight + corner.y * gUp + sqrt(1.0 - r2) * gToEye);
#endif
  float sceneDistance = viewDistance(texelFetch(uSceneDepth, ivec2(gl_FragCoord.xy), 0).r);
  float particleDistance = viewDistance(gl_FragCoord.z);
  float fade = clamp((sceneDistance - particleDistance) / max(look.params.y, 1e-4), 0.0, 1.0);
  float alpha = mix(look.colorBirth.a, look.colorDeath.a, age) * shape * fade;
#ifdef POINTS
  alpha = shape * (fade > 0.0 ? 1.0 : 0.0);  // opaque points, hidden behind the scene
#endif
  if (alpha < 1.0 / 512.0) discard;
  vec3 color = colorAt(colorT);
  outColor = vec4(color * alpha, alpha);
  outNormal = vec4(normal * alpha, alpha);
  outLight = vec4(light * alpha, 0.0, 0.0, alpha);
}
