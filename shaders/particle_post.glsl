// ParticlePost: deferred particle shading (thesis 5.1.3), shared by the
// raster pass (particle_post.frag) and the compute pass (particle_post.comp).
// The accumulated particles are lit once per pixel from their accumulated
// billboard normals and the light direction, then composited (premultiplied
// "over") onto the scene, seen through the lit haze (render.scattering; the
// particles are drawn over it, in front of the haze behind them). Needs
// view_block.glsl, render_block.glsl, shadow_block.glsl and
// light_scattering.glsl.
layout(binding = 0) uniform sampler2D uSceneColor;
layout(binding = 1) uniform sampler2D uParticleColor;
layout(binding = 2) uniform sampler2D uParticleNormal;
layout(binding = 3) uniform sampler2D uParticleLight;  // premultiplied share of the light (shadows)
layout(binding = 4) uniform sampler2D uSceneDepth;

// The composite at the view's pixel p.
vec4 compositeAt(ivec2 p) {
  vec4 scene = texelFetch(uSceneColor, p, 0);
  if (look.haze.x > 0.0) {
    vec2 ndc = (vec2(p) + 0.5) / view.viewport.zw * 2.0 - 1.0;
    float depth = texelFetch(uSceneDepth, p, 0).r;
    vec4 far = view.inverseViewProjection * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    vec3 to = far.xyz / far.w - view.eye.xyz;
    float distance = length(to);
    scene.rgb = throughHaze(scene.rgb, to / max(distance, 1e-6), distance, depth >= 1.0);
  }
  vec4 particles = texelFetch(uParticleColor, p, 0);
  vec3 lit = particles.rgb;
  if (look.params.z > 0.5 && particles.a > 0.0) {
    vec3 accumulated = texelFetch(uParticleNormal, p, 0).xyz;
    float len = length(accumulated);
    vec3 n = len > 1e-6 ? accumulated / len : look.lightDirection.xyz;
    float ambient = look.lightDirection.w;
    // The shadows dim the direct light only: the sky's ambient light comes from everywhere.
    float reach = look.light.w > 0.5 ? clamp(texelFetch(uParticleLight, p, 0).r / particles.a, 0.0, 1.0) : 1.0;
    lit *= ambient + (1.0 - ambient) * max(dot(n, look.lightDirection.xyz), 0.0) * reach * look.light.rgb;
  }
  return vec4(lit + scene.rgb * (1.0 - particles.a), 1.0);
}
