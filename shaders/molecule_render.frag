#version 450 core
// MoleculeRenderer: premultiplied colour, normal and light into the
// particle buffers, as particle_render.frag writes them, so ParticlePost
// lights molecules and particles in one deferred pass. Hidden behind the
// scene and faded near it as particles are.
#include "view_block.glsl"
#include "render_block.glsl"

layout(binding = 3) uniform sampler2D uSceneDepth;

in vec3 vPosition;
in vec3 vNormal;
flat in int vRibbon;
in float vAcross;
in float vAge;
in float vColor;
in float vLight;
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outLight;

void main() {
  vec3 toEye = normalize(view.eye.xyz - vPosition);
  vec3 normal;
  if (vRibbon != 0) {
    float s = clamp(vAcross, -1.0, 1.0);
    vec3 across = normalize(vNormal);
    vec3 facing = normalize(toEye - across * dot(toEye, across));
    normal = normalize(s * across + sqrt(max(1.0 - s * s, 0.0)) * facing);
  } else {
    normal = dot(vNormal, toEye) < 0.0 ? -vNormal : vNormal;
  }
  float sceneDistance = viewDistance(texelFetch(uSceneDepth, ivec2(gl_FragCoord.xy), 0).r);
  float distance = viewDistance(gl_FragCoord.z);
  float fade = clamp((sceneDistance - distance) / max(look.params.y, 1e-4), 0.0, 1.0);
  float alpha = mix(look.colorBirth.a, look.colorDeath.a, vAge) * fade;
  if (alpha < 1.0 / 512.0) discard;
  vec3 color = colorAt(vColor);
  outColor = vec4(color * alpha, alpha);
  outNormal = vec4(normal * alpha, alpha);
  outLight = vec4(vLight * alpha, 0.0, 0.0, alpha);
}
