// The ground's and the sky's colours, shared by the raster terrain
// (terrain.frag) and the compute background (scene_background.comp) so both
// draw the same scene. Needs view_block.glsl, render_block.glsl and
// shadow_block.glsl.

// Sand lit by the scene light through the dust's shadow, with a one-metre
// grid so scale and depth read at a glance. `width`: how far the point moves
// in x and y from one pixel to the next (fwidth), for lines one pixel wide.
vec3 groundColor(vec3 position, vec3 normal, vec2 width) {
  vec3 direct = max(dot(normal, look.lightDirection.xyz), 0.0) * lightTransmittance(position) * look.light.rgb;
  vec3 sand = vec3(0.76, 0.66, 0.50);
  vec2 cell = abs(fract(position.xy + 0.5) - 0.5) / width;
  float line = 1.0 - clamp(min(cell.x, cell.y), 0.0, 1.0);
  float distance = length(position - view.eye.xyz);
  line *= clamp(1.0 - distance / 40.0, 0.0, 1.0);
  vec3 color = sand * (0.45 + 0.55 * direct);
  return mix(color, color * 0.7, line * 0.6);
}

// A sky gradient by the view direction `dir` (unit).
vec3 skyColor(vec3 dir) {
  float h = clamp(dir.z, -1.0, 1.0);
  vec3 horizon = vec3(0.86, 0.80, 0.72), zenith = vec3(0.36, 0.55, 0.82), below = vec3(0.45, 0.40, 0.35);
  return h >= 0.0 ? mix(horizon, zenith, pow(h, 0.6)) : mix(horizon, below, pow(-h, 0.5));
}
