// A particle's splat: the pixels its billboard (particle_render.geom) covers
// and what it adds to each, shared by the atomic and the tiled splat passes
// so both add exactly the same numbers. Needs view_block.glsl,
// render_block.glsl, splat_common.glsl and the sampler bindings below.
#include "shadow_block.glsl"
#include "motion_blur.glsl"

layout(binding = 2) uniform sampler2D uSprite;      // R8 puff, as ParticleRender's
layout(binding = 3) uniform sampler2D uSceneDepth;  // the scene's depth, this view's size

// Pixels of its level: larger particles are drawn this large (levels draw
// them on coarser grids first; past the last, use billboards). Below 16 so a
// still splat spans at most 33 pixels, two 32-pixel tiles, a side.
const float kMaxRadius = 15.5;
// Pixels: motion blur smears a splat at most this far (render.shutter).
const float kMaxSmear = 48.0;
// The centre's window coordinates in a record: fixed point, 1/8 pixel, from
// -64 (so views up to 8127 pixels wide; farther splats are not drawn).
const float kPixelSteps = 8.0, kPixelOrigin = 64.0;

struct Splat {
  vec2 pixel;     // window coordinates of the centre
  vec2 radius;    // pixels
  vec2 invRadius; // 1 / radius
  vec3 right, up, toEye;
  float distance; // camera-space distance of the centre
  float opacity;
  float age;
  float color;    // the colour map's coordinate
  float light;    // the share of the light reaching it through the dust
  vec2 motion;    // motion blur: where the centre was when the shutter opened, negated (radii)
#ifdef MOTION_FILTER
  vec2 flow;      // the same in view pixels, for the filter (the splat itself is not smeared)
#endif
  ivec2 lo, hi;   // the pixels it may cover (inclusive, inside the view)
  int level;      // the grid it is drawn on (splat_common.glsl): pixel, radius,
                  // motion, lo and hi are in that level's pixels
};

// How many levels this view's splats may use (ParticleSplat: 1 with
// render.splat_detail 0, or where the levels' tiles do not fit the histogram).
layout(location = 15) uniform int uSplatLevels;

// The splat's radii in view pixels, before any level or limit.
vec2 splatViewRadius(float distance) {
  return 0.5 * look.params.x * vec2(view.projection[0][0], view.projection[1][1]) * 0.5 * view.viewport.zw / distance;
}

// The level a splat of those radii is drawn at: the coarsest on whose grid
// it is still at least render.splat_detail pixels wide, so it is drawn
// between detail and twice that wide (halving is exact, so every pass that
// asks gets the same level).
int splatLevel(vec2 radius) {
  float r = max(radius.x, radius.y), detail = look.splat.x;
  int level = 0;
  while (level + 1 < uSplatLevels && r >= detail) {
    r *= 0.5;
    ++level;
  }
  return level;
}

// The level of a record's splat (its first three words).
int splatLevelOf(uvec3 where) { return splatLevel(splatViewRadius(uintBitsToFloat(where.y))); }

// A splat in 16 bytes, as the tiled pass lists it and both passes use it (so
// both add the same integers): the centre's window coordinates (16-bit fixed
// point each), its distance (a float), its motion over the shutter in pixels
// (two halves), and the age (10 bits), the colour map's coordinate (12) and
// the share of the light reaching it (10: shadow_block.glsl). The direction
// to the eye is not stored: the centre lies on the eye's ray through its
// pixel, so unpackSplat finds it from the pixel.
// A record's first three words: the centre's window coordinates, distance
// and motion. False when the particle is behind the eye (or at it) or
// beyond the coordinates' range.
bool splatCentre(vec3 center, vec3 velocity, out uvec3 where) {
  vec4 clip = view.viewProjection * vec4(center, 1.0);
  vec3 toEye = view.eye.xyz - center;
  if (clip.w <= 1e-4 || dot(toEye, toEye) < 1e-8) return false;
  vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * view.viewport.zw;
  vec2 fixedPixel = round((pixel + kPixelOrigin) * kPixelSteps);
  if (any(lessThan(fixedPixel, vec2(0.0))) || any(greaterThan(fixedPixel, vec2(65535.0)))) return false;
  // Motion blur: the centre's pixel when the shutter opened, on the same side of the eye.
  vec2 motion = vec2(0.0);
#if defined(MOTION_BLUR) || defined(MOTION_FILTER)
  if (look.params.w > 0.0) {
    vec4 before = view.viewProjection * vec4(center - velocity * look.params.w, 1.0);
    if (before.w > 1e-4) motion = pixel - (before.xy / before.w * 0.5 + 0.5) * view.viewport.zw;
    float smear = length(motion);
    if (smear > kMaxSmear) motion *= kMaxSmear / smear;
  }
#endif
  uvec2 fixedBits = uvec2(fixedPixel);
  where = uvec3(fixedBits.x | fixedBits.y << 16, floatBitsToUint(clip.w), packHalf2x16(motion));
  return true;
}

// A record's last word: the age, the colour map's coordinate and the light.
uint splatLook(vec4 positionLife, vec4 velocityKind) {
  float age = clamp(1.0 - positionLife.w / max(velocityKind.w, 1e-6), 0.0, 1.0);
  float color = colorCoordinate(age, velocityKind.xyz, positionLife.xyz);
#ifdef SHADOWS
  float light = clamp(lightTransmittance(positionLife.xyz), 0.0, 1.0);
#else
  float light = 1.0;
#endif
  return uint(round(age * 1023.0)) | uint(round(color * 4095.0)) << 10 | uint(round(light * 1023.0)) << 22;
}

bool makeSplatRecord(vec4 positionLife, vec4 velocityKind, out uvec4 record) {
  uvec3 where;
  if (!splatCentre(positionLife.xyz, velocityKind.xyz, where)) return false;
  record = uvec4(where, splatLook(positionLife, velocityKind));
  return true;
}

// Where a splat is, from its record's first three words, on the grid of
// `level`: its centre and radius in that level's pixels and the pixels it
// may cover. False when it shows nowhere in this view.
bool splatBounds(uvec3 where, int level, out Splat s) {
  float scale = 1.0 / float(1 << level);
  s.level = level;
  s.pixel = (vec2(float(where.x & 65535u), float(where.x >> 16)) / kPixelSteps - kPixelOrigin) * scale;
  s.distance = uintBitsToFloat(where.y);
#ifdef MOTION_BLUR
  vec2 motion = unpackHalf2x16(where.z) * scale;
#else
  const vec2 motion = vec2(0.0);
#endif
  vec2 size = vec2(splatLevelSize(ivec2(view.viewport.zw), level));
  s.radius = min(splatViewRadius(s.distance) * scale, vec2(kMaxRadius));
#ifdef MOTION_FILTER
  s.flow = unpackHalf2x16(where.z);
#endif
  vec2 least = min(s.pixel, s.pixel - motion) - s.radius, greatest = max(s.pixel, s.pixel - motion) + s.radius;
  if (greatest.x < 0.0 || greatest.y < 0.0 || least.x > size.x || least.y > size.y) return false;
  s.invRadius = 1.0 / s.radius;
  s.motion = motion * s.invRadius;
  s.lo = max(ivec2(floor(least)), ivec2(0));
  s.hi = min(ivec2(ceil(greatest)), ivec2(size) - 1);
  return s.lo.x <= s.hi.x && s.lo.y <= s.hi.y;
}

// The whole splat from its record, on the grid of `level`. False when it
// shows nowhere in this view.
bool unpackSplat(uvec4 record, int level, out Splat s) {
  if (!splatBounds(record.xyz, level, s)) return false;
  s.age = float(record.w & 1023u) / 1023.0;
  s.color = float((record.w >> 10) & 4095u) / 4095.0;
  s.light = float(record.w >> 22) / 1023.0;
  // The eye's ray through the centre's pixel, to the far plane.
  vec4 far = view.inverseViewProjection * vec4(s.pixel * float(1 << level) / view.viewport.zw * 2.0 - 1.0, 1.0, 1.0);
  s.toEye = normalize(view.eye.xyz - far.xyz / far.w);
  // The billboard's frame, as particle_render.geom builds it.
  vec3 worldUp = abs(s.toEye.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
  s.right = normalize(cross(worldUp, s.toEye));
  s.up = cross(s.toEye, s.right);
  s.opacity = mix(look.colorBirth.a, look.colorDeath.a, s.age);
  return true;
}

// False when the particle shows nowhere in this view.
bool makeSplat(vec4 positionLife, vec4 velocityKind, out Splat s) {
  uvec4 record;
  return makeSplatRecord(positionLife, velocityKind, record) && unpackSplat(record, splatLevelOf(record.xyz), s);
}

#ifdef MOTION_BLUR
// Where x lies when c1 x + c0 is within [low, high]: narrows [from, to].
void narrow(float c1, float c0, float low, float high, inout float from, inout float to) {
  if (abs(c1) < 1e-6) {
    if (c0 < low || c0 > high) to = from - 1.0;
    return;
  }
  float a = (low - c0) / c1, b = (high - c0) / c1;
  from = max(from, min(a, b));
  to = min(to, max(a, b));
}

// A smear's row dy (in radii): the x (in radii) within 1 of its path from -m
// to 0, the union of the end discs' rows and the strip between them (one
// interval: the smear is convex). Empty: from > to.
vec2 smearRow(vec2 m, float dy) {
  vec2 row = vec2(1e30, -1e30);
  for (int e = 0; e < 2; ++e) {
    vec2 c = e == 0 ? vec2(0.0) : -m;
    float d = dy - c.y;
    if (abs(d) <= 1.0) row = vec2(min(row.x, c.x - sqrt(1.0 - d * d)), max(row.y, c.x + sqrt(1.0 - d * d)));
  }
  float len = length(m);
  vec2 a = m / len, n = vec2(-a.y, a.x);
  float from = -1e30, to = 1e30;  // along the path 0..len from its start, within 1 across it
  narrow(a.x, a.x * m.x + a.y * (dy + m.y), 0.0, len, from, to);
  narrow(n.x, n.x * m.x + n.y * (dy + m.y), -1.0, 1.0, from, to);
  if (from <= to) row = vec2(min(row.x, from), max(row.y, to));
  return row;
}
#endif

// The pixels of row y (between lo.x and hi.x) whose centres may lie inside the
// splat's ellipse (or smear): the loops visit only these (splatAt still tests
// each; a pixel at the very rim, where the puff is transparent, may be skipped).
ivec2 splatRow(Splat s, int y) {
  float dy = (float(y) + 0.5 - s.pixel.y) * s.invRadius.y;
#ifdef MOTION_BLUR
  if (s.motion != vec2(0.0)) {
    vec2 row = smearRow(s.motion, dy);
    if (row.x > row.y) return ivec2(1, 0);
    return ivec2(max(s.lo.x, int(ceil(s.pixel.x + row.x * s.radius.x - 0.5))),
                 min(s.hi.x, int(floor(s.pixel.x + row.y * s.radius.x - 0.5))));
  }
#endif
  float halfWidth = sqrt(max(1.0 - dy * dy, 0.0)) * s.radius.x;
  return ivec2(max(s.lo.x, int(ceil(s.pixel.x - halfWidth - 0.5))), min(s.hi.x, int(floor(s.pixel.x + halfWidth - 0.5))));
}

// What the splat adds to pixel p, as kSplatChannels fixed-point values
// (splat_common.glsl); false where it adds nothing.
bool splatAt(Splat s, ivec2 p, out uint v[kSplatChannels]) {
  vec2 corner = (vec2(p) + 0.5 - s.pixel) * s.invRadius;
#ifdef MOTION_BLUR
  float shape;
  if (s.motion != vec2(0.0)) {  // as particle_render.frag's
    vec2 closest;
    shape = smearedPuff(corner, s.motion, closest) * puffLumps(closest);
    corner = closest;
  }
  float r2 = dot(corner, corner);
  if (r2 > 1.0) return false;
  if (s.motion == vec2(0.0)) shape = textureLod(uSprite, 0.5 * corner + 0.5, 0.0).r;
#else
  float r2 = dot(corner, corner);
  if (r2 > 1.0) return false;
  float shape = textureLod(uSprite, 0.5 * corner + 0.5, 0.0).r;
#endif
  // The scene's depth at the view pixel under the level pixel's centre.
  ivec2 under = min(p * (1 << s.level) + ((1 << s.level) >> 1), ivec2(view.viewport.zw) - 1);
  float sceneDistance = viewDistance(texelFetch(uSceneDepth, under, 0).r);
  float fade = clamp((sceneDistance - s.distance) / max(look.params.y, 1e-4), 0.0, 1.0);
  float alpha = s.opacity * shape * fade;
  if (alpha < 1.0 / 512.0) return false;
  // A unit vector: right, up and toEye are orthonormal.
  vec3 normal = corner.x * s.right + corner.y * s.up + sqrt(1.0 - r2) * s.toEye;
  float opticalDepth = -log(1.0 - min(alpha, 0.999));
#ifdef SHADOWS
  float weight = opticalDepth;  // splat_common.glsl
  v[0] = uint(weight * s.light * kSplatScale + 0.5);
#else
  float weight = alpha;
  v[0] = uint(alpha * kSplatScale + 0.5);
#endif
  v[1] = uint(weight * s.color * kSplatScale + 0.5);
  v[2] = uint(opticalDepth * kSplatScale + 0.5);
  ivec3 nn = ivec3(round(weight * normal * kSplatScale));
  v[3] = uint(nn.x);
  v[4] = uint(nn.y);
  v[5] = uint(nn.z);
  return true;
}

#ifdef MOTION_FILTER
// What a splat adds to a tile's motion sums (splat_common.glsl): w m and
// w times m's doubled-angle axis (half pixels), and w, shifted right by `shift`.
void splatMotionSums(Splat s, int shift, out ivec4 motion, out int weight) {
  float len = length(s.flow);
  vec2 axis = len > 0.0 ? vec2(s.flow.x * s.flow.x - s.flow.y * s.flow.y, 2.0 * s.flow.x * s.flow.y) / len : vec2(0.0);
  int w = int(round(s.opacity * 16.0));
  motion = ivec4(round(2.0 * vec4(s.flow, axis))) * w >> shift;
  weight = w >> shift;
}
#endif

// The particle buffers' values from a pixel's sums (as floats, the normal's
// signed, every level's added): alpha is "over"'s, 1 - prod(1 - alpha_i);
// colour, normal and light are weighted means (by alpha, or with SHADOWS by
// -ln(1 - alpha): splat_common.glsl) times it.
void resolveSplat(float sums[kSplatChannels], out vec4 color, out vec4 normal, out float light) {
  color = vec4(0.0);
  normal = vec4(0.0);
  light = 0.0;
#ifdef SHADOWS
  float weight = sums[2];
#else
  float weight = sums[0];
#endif
  if (weight <= 0.0) return;
  float alpha = 1.0 - exp(-sums[2] / kSplatScale);
  // The alpha-weighted mean coordinate: the mean colour where the map is linear
  // (life), and close to it where it bends slowly (the perceptual maps).
  float t = sums[1] / weight;
  color = vec4(colorAt(t) * alpha, alpha);
  normal = vec4(vec3(sums[3], sums[4], sums[5]) / weight * alpha, alpha);
#ifdef SHADOWS
  light = sums[0] / weight * alpha;
#else
  light = alpha;
#endif
}
