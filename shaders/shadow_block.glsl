// The opacity shadow map (OpacityShadowMap, core/light/light_model.h): how
// much light reaches a point through the dust. The block is written on the
// GPU by shadow_frame.comp each frame; the map holds, for each texel across
// the light, the optical depth accumulated from the light down to each of
// layers + 1 boundaries (0 at the first), so linear filtering between two
// boundaries is the optical depth at a depth between them.
layout(std140, binding = 4) uniform ShadowBlock {
  vec4 right;    // xyz: the light frame's first axis across the light; w: 1 with shadows
  vec4 up;       // xyz: its second axis; w: 1 / cell size (1/m)
  vec4 toLight;  // xyz: towards the light; w: layers
  vec4 corner;   // x, y: the map's least corner along right and up (m); z: the top
                 // (nearest the light) along toLight; w: 1 / the depth the layers span
  vec4 params;   // x: optical depth per unit cross-section in a cell (1 / cell area),
                 // y: the map's texture side, z, w: the cells the map uses along right, up
} shadow;
layout(binding = 7) uniform sampler3D uShadowDepth;

// Where x lies in the map: cell coordinates across the light and depth in
// layers from the top.
vec3 shadowCoordinates(vec3 x) {
  vec2 across = (vec2(dot(x, shadow.right.xyz), dot(x, shadow.up.xyz)) - shadow.corner.xy) * shadow.up.w;
  float depth = (shadow.corner.z - dot(x, shadow.toLight.xyz)) * shadow.corner.w * shadow.toLight.w;
  return vec3(across, depth);
}

// The fraction of the light that reaches x (1 without shadows or outside the map).
float lightTransmittance(vec3 x) {
  if (shadow.right.w == 0.0) return 1.0;
  vec3 c = shadowCoordinates(x);
  if (c.x < 0.0 || c.y < 0.0 || c.x > shadow.params.z || c.y > shadow.params.w) return 1.0;
  float layers = shadow.toLight.w;
  float depth = clamp(c.z, 0.0, layers);
  float tau = texture(uShadowDepth, vec3(c.xy / shadow.params.y, (depth + 0.5) / (layers + 1.0))).r;
  return exp(-tau);
}
