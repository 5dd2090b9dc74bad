#version 450 core
// ParticleMotionFilter, step 3: motion blur (render.shutter, render.blur =
// filter) as a gather over the splats' particle buffers. A splat that moved
// by m pixels over the shutter covers, averaged over that time, its still
// footprint swept back along m, with 1/|m| of its weight a pixel of path. So
// a pixel p receives from the pixels q = p + u a ahead of it along an axis a
// whose motion along a (speed s) reaches back to p, with the share of the
// shutter their paths spend over p (1/s a pixel of path, integrated over
// each tap's stretch), and from the pixels behind it that move the other
// way; p's own content stays for the half pixel it takes to leave: the box
// shutter's smear of a layer moving with the pixels, conserving opacity.
// The buffers hold premultiplied values, so averaging them averages what
// covers p over the shutter time.
//
// A pixel's splats may move different ways (a vortex's front and back cross
// it in opposite directions): the motion field (particle_motion_field.comp,
// interpolated between 8-pixel cells) gives each pixel its splats' mean
// motion and the mean of its axis with the angle doubled (splat_common.glsl),
// and the filter takes a pixel's splats as moving along that axis at that speed,
// the share (1 + mean / speed) / 2 of them forwards and the rest backwards.
// One direction moves as it should; opposite ones each smear both ways, as
// long in all. The axis is the pixel's own where it moves, else the longest
// motion that reaches its 16-pixel tile (particle_motion_reach.comp);
// samples moving across the axis are not gathered (the approximation of a
// reconstruction filter (McGuire et al. 2012)). Where the weights fall short
// of 1 the pixel keeps the mean of what it gathered (below).
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) uniform sampler2D uColorIn;  // the resolve's, unblurred (linear filtering)
layout(binding = 1) uniform sampler2D uNormalIn;
layout(binding = 2) uniform sampler2D uLightIn;
layout(binding = 3) uniform sampler2D uCells;   // the motion's and its axis's means, 8-pixel cells (linear)
layout(binding = 5) uniform sampler2D uReach;   // the longest axis reaching a tile
layout(rgba16f, binding = 0) writeonly uniform image2D uColor;
layout(rgba16f, binding = 1) writeonly uniform image2D uNormal;
layout(r16f, binding = 2) writeonly uniform image2D uLight;
layout(location = 0) uniform ivec2 uSize;

const int kMotionTile = 16, kCell = 8;
// Samples a side: at most 2 pixels apart over a 48-pixel smear.
const int kMaxTaps = 24;
// Pixels: nothing around moving this far, the pixel is kept as it is.
const float kStill = 0.5;

// The unit direction of an axis given with its angle doubled.
vec2 axisDirection(vec2 doubled) {
  vec2 v = vec2(length(doubled) + doubled.x, doubled.y);
  return dot(v, v) > 1e-12 ? normalize(v) : vec2(0.0, 1.0);
}

// The integral from the pixel's edge (0.5) to x of the share of the shutter
// a path [x' - s, x'] spends over the pixel [-0.5, 0.5]: min(s + 0.5 - x', 1),
// down to 0 at x' = s + 0.5.
float coverTime(float x, float s) {
  float full = s - 0.5, end = s + 0.5;
  float hi = clamp(x, 0.5, end);
  float whole = max(min(hi, full) - 0.5, 0.0);  // where the whole shutter is spent over it
  float lo = max(0.5, full);
  float slope = hi > lo ? end * (hi - lo) - 0.5 * (hi * hi - lo * lo) : 0.0;
  return whole + slope;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= uSize.x || p.y >= uSize.y) return;
  vec2 toCells = 1.0 / (float(kCell) * vec2(textureSize(uCells, 0)));
  vec2 own = textureLod(uCells, (vec2(p) + 0.5) * toCells, 0.0).zw;
  vec2 near = texelFetch(uReach, p / kMotionTile, 0).xy;
  float ownLength = length(own), reach = max(length(near), ownLength);
  vec4 color = texelFetch(uColorIn, p, 0), normal = texelFetch(uNormalIn, p, 0);
  float total = 1.0;  // the weights: 1 where the motion is uniform
#ifdef SHADOWS
  float light = texelFetch(uLightIn, p, 0).r;
#endif
  if (reach >= kStill) {
    vec2 a = axisDirection(ownLength >= kStill ? own : near);
    // The pixel's own content covers it for the time it takes to leave: half
    // a pixel at its speed along the axis.
    float self = min(1.0, 0.5 / max(ownLength * abs(dot(axisDirection(own), a)), 1e-6));
    color *= self;
    normal *= self;
    total = self;
#ifdef SHADOWS
    light *= self;
#endif
    // Samples beyond the pixel's half width, each standing for du pixels of
    // path, out to the longest reach around.
    int taps = clamp(int(ceil(reach / 2.0)), 1, kMaxTaps);
    float du = reach / float(taps);
    vec2 invSize = 1.0 / vec2(uSize);
    for (int side = 0; side < 2; ++side) {
      vec2 d = side == 0 ? a : -a;
      for (int k = 0; k < taps; ++k) {
        float u = 0.5 + (float(k) + 0.5) * du;
        vec2 q = vec2(p) + 0.5 + u * d;  // window coordinates of the sample
        if (any(lessThan(q, vec2(0.0))) || any(greaterThanEqual(q, vec2(uSize)))) break;
        vec4 m = textureLod(uCells, q * toCells, 0.0);
        float s = length(m.zw) * abs(dot(axisDirection(m.zw), a));  // its speed along the axis
        // The time the paths [x - s, x] of its stretch x in [u - du/2, u + du/2]
        // spend over this pixel [-0.5, 0.5], integrated exactly.
        float covers = coverTime(u + 0.5 * du, s) - coverTime(u - 0.5 * du, s);
        if (covers <= 0.0) continue;
        float towards = clamp(0.5 + 0.5 * dot(m.xy, d) / s, 0.0, 1.0);  // the share moving along d
        float w = towards * covers / s;
        total += w;
        vec2 at = q * invSize;
        color += w * textureLod(uColorIn, at, 0.0);
        normal += w * textureLod(uNormalIn, at, 0.0);
#ifdef SHADOWS
        light += w * textureLod(uLightIn, at, 0.0).r;
#endif
      }
    }
  }
  // Where the motion varies, the weights need not add up to 1. Less: the
  // pixel's content left and what the model says came in did not (paths
  // diverging, crossing the axis, or leaving the view): the mean of what was
  // gathered stands for the rest, rather than a hole the sky shows through.
  // More: smears overlap, adding opacities "over" would saturate: keep the
  // mean's colour and cap its opacity at 1.
  float over = total < 1.0 ? total : max(color.a, 1.0);
  color /= over;
  normal /= over;
#ifdef SHADOWS
  light /= over;
#else
  float light = color.a;  // without shadows the light buffer is the opacity (splat_footprint.glsl)
#endif
  imageStore(uColor, p, color);
  imageStore(uNormal, p, normal);
  imageStore(uLight, p, vec4(light));
}
