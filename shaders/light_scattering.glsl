// Light scattering (render.scattering, thesis 7.2: "light scattering could be
// used to give the illusion that particles are blocking out light"): the air
// holds a thin haze of density beta that scatters the light towards the eye,
// except where the dust's shadow (the opacity layers, shadow_block.glsl)
// keeps the light from it, so shafts of light and shadow show through the air.
// Marched in the light's 3D volume rather than by a screen-space radial blur
// from the light's image: the same haze lies behind every wall of a CAVE,
// unbroken at the seams, and the light need not be in view.
// Needs view_block.glsl, render_block.glsl and shadow_block.glsl.

const int kScatterSteps = 48;
const float kHazeAlbedo = 0.85;  // the share of the light the haze sends on (near the sky's horizon)

// The scene seen through `distance` metres of haze along `dir` from the eye:
// the scene dimmed by exp(-beta d), plus the light the haze scatters. The
// sky (`sky`) already is the hazy atmosphere: it only loses the light the
// dust's shadow keeps from the haze in front of it.
vec3 throughHaze(vec3 scene, vec3 dir, float distance, bool sky) {
  float beta = look.haze.x;
  if (beta <= 0.0) return scene;
  float d = sky ? 6.0 / beta : min(distance, 6.0 / beta);  // farther haze is opaque to 0.25%
  float seen = sky ? 1.0 : exp(-beta * d);
  // The light the haze would scatter unshadowed, less what the dust's
  // shadow takes from it: integral of (1 - T(x)) beta exp(-beta s) ds,
  // marched where the shadow map lies along the ray (below the cloud too).
  float shadowed = 0.0;
  if (shadow.right.w != 0.0) {
    vec3 c0 = shadowCoordinates(view.eye.xyz), c1 = shadowCoordinates(view.eye.xyz + dir) - c0;
    float s0 = 0.0, s1 = d;
    for (int a = 0; a < 2; ++a) {  // the map's extent across the light
      float hi = a == 0 ? shadow.params.z : shadow.params.w;
      if (abs(c1[a]) < 1e-9) {
        if (c0[a] < 0.0 || c0[a] > hi) s1 = -1.0;
      } else {
        float ta = -c0[a] / c1[a], tb = (hi - c0[a]) / c1[a];
        s0 = max(s0, min(ta, tb));
        s1 = min(s1, max(ta, tb));
      }
    }
    if (abs(c1.z) > 1e-9) {  // below the map's top (depth >= 0)
      float t = -c0.z / c1.z;
      if (c1.z > 0.0) s0 = max(s0, t); else s1 = min(s1, t);
    } else if (c0.z < 0.0) {
      s1 = -1.0;
    }
    if (s1 > s0) {
      float step = (s1 - s0) / float(kScatterSteps);
      for (int i = 0; i < kScatterSteps; ++i) {
        float s = s0 + (float(i) + 0.5) * step;
        shadowed += (1.0 - lightTransmittance(view.eye.xyz + s * dir)) * beta * exp(-beta * s) * step;
      }
    }
  }
  vec3 haze = kHazeAlbedo * look.light.rgb;
  if (sky) return max(scene - haze * shadowed, vec3(0.0));
  return scene * seen + haze * max(1.0 - seen - shadowed, 0.0);
}
