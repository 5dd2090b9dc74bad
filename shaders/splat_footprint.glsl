// A particle's splat: the pixels its billboard (particle_render.geom) covers
// and what it adds to each, shared by the atomic and the tiled splat passes
// so both add exactly the same numbers. Needs view_block.glsl,
// render_block.glsl, splat_common.glsl and the sampler bindings below.

layout(binding = 2) uniform sampler2D uSprite;      // R8 puff, as ParticleRender's
layout(binding = 3) uniform sampler2D uSceneDepth;  // the scene's depth, this view's size

// Pixels: larger particles are drawn this large (use billboards for them).
// Below 16 so a splat spans at most 33 pixels, two 32-pixel tiles, a side.
const float kMaxRadius = 15.5;

struct Splat {
  vec2 pixel;     // window coordinates of the centre
  vec2 radius;    // pixels
  vec2 invRadius; // 1 / radius
  vec3 right, up, toEye;
  float distance; // camera-space distance of the centre
  float opacity;
  float age;
  ivec2 lo, hi;   // the pixels it may cover (inclusive, inside the view)
};

// A splat in 16 bytes, as the tiled pass lists it and both passes use it (so
// both add the same integers): the centre's window coordinates and distance
// as floats; the age in 10 bits and the direction to the eye in 2 x 11 bits
// (octahedral: a tenth of a degree, far below what lighting a 4-pixel puff shows).
vec2 octahedral(vec3 n) {
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 signs = vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  return n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * signs;
}

vec3 fromOctahedral(vec2 p) {
  vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
  vec2 signs = vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * signs;
  return normalize(n);
}

// A record's first three words: the centre's window coordinates and
// distance. False when the particle is behind the eye (or at it).
bool splatCentre(vec3 center, out uvec3 where) {
  vec4 clip = view.viewProjection * vec4(center, 1.0);
  vec3 toEye = view.eye.xyz - center;
  if (clip.w <= 1e-4 || dot(toEye, toEye) < 1e-8) return false;
  where = uvec3(floatBitsToUint((clip.xy / clip.w * 0.5 + 0.5) * view.viewport.zw), floatBitsToUint(clip.w));
  return true;
}

// A record's last word: the age and the direction to the eye.
uint splatLook(vec3 center, float life, float lifetime) {
  float age = clamp(1.0 - life / max(lifetime, 1e-6), 0.0, 1.0);
  uvec2 direction = uvec2(round((octahedral(view.eye.xyz - center) * 0.5 + 0.5) * 2047.0));
  return uint(round(age * 1023.0)) | direction.x << 10 | direction.y << 21;
}

bool makeSplatRecord(vec4 positionLife, vec4 velocityKind, out uvec4 record) {
  uvec3 where;
  if (!splatCentre(positionLife.xyz, where)) return false;
  record = uvec4(where, splatLook(positionLife.xyz, positionLife.w, velocityKind.w));
  return true;
}

// Where a splat is, from its record's first three words: its centre and
// radius in pixels and the pixels it may cover. False when it shows nowhere
// in this view.
bool splatBounds(uvec3 where, out Splat s) {
  s.pixel = uintBitsToFloat(where.xy);
  s.distance = uintBitsToFloat(where.z);
  vec2 size = view.viewport.zw;
  float radius = 0.5 * look.params.x;
  s.radius = min(radius * vec2(view.projection[0][0], view.projection[1][1]) * 0.5 * size / s.distance, vec2(kMaxRadius));
  if (s.pixel.x + s.radius.x < 0.0 || s.pixel.y + s.radius.y < 0.0 || s.pixel.x - s.radius.x > size.x ||
      s.pixel.y - s.radius.y > size.y)
    return false;
  s.invRadius = 1.0 / s.radius;
  s.lo = max(ivec2(floor(s.pixel - s.radius)), ivec2(0));
  s.hi = min(ivec2(ceil(s.pixel + s.radius)), ivec2(size) - 1);
  return s.lo.x <= s.hi.x && s.lo.y <= s.hi.y;
}

// The whole splat from its record. False when it shows nowhere in this view.
bool unpackSplat(uvec4 record, out Splat s) {
  if (!splatBounds(record.xyz, s)) return false;
  s.age = float(record.w & 1023u) / 1023.0;
  s.toEye = fromOctahedral(vec2(uvec2(record.w >> 10, record.w >> 21) & 2047u) / 2047.0 * 2.0 - 1.0);
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
  return makeSplatRecord(positionLife, velocityKind, record) && unpackSplat(record, s);
}

// The pixels of row y (between lo.x and hi.x) whose centres may lie inside the
// splat's ellipse: the loops visit only these (splatAt still tests each;
// a pixel at the very rim, where the puff is transparent, may be skipped).
ivec2 splatRow(Splat s, int y) {
  float dy = (float(y) + 0.5 - s.pixel.y) * s.invRadius.y;
  float halfWidth = sqrt(max(1.0 - dy * dy, 0.0)) * s.radius.x;
  return ivec2(max(s.lo.x, int(ceil(s.pixel.x - halfWidth - 0.5))), min(s.hi.x, int(floor(s.pixel.x + halfWidth - 0.5))));
}

// What the splat adds to pixel p, as kSplatChannels fixed-point values
// (splat_common.glsl); false where it adds nothing.
bool splatAt(Splat s, ivec2 p, out uint v[kSplatChannels]) {
  vec2 corner = (vec2(p) + 0.5 - s.pixel) * s.invRadius;
  float r2 = dot(corner, corner);
  if (r2 > 1.0) return false;
  float shape = textureLod(uSprite, 0.5 * corner + 0.5, 0.0).r;
  float sceneDistance = viewDistance(texelFetch(uSceneDepth, p, 0).r);
  float fade = clamp((sceneDistance - s.distance) / max(look.params.y, 1e-4), 0.0, 1.0);
  float alpha = s.opacity * shape * fade;
  if (alpha < 1.0 / 512.0) return false;
  // A unit vector: right, up and toEye are orthonormal.
  vec3 normal = corner.x * s.right + corner.y * s.up + sqrt(1.0 - r2) * s.toEye;
  v[0] = uint(alpha * kSplatScale + 0.5);
  v[1] = uint(alpha * s.age * kSplatScale + 0.5);
  v[2] = uint(-log(1.0 - min(alpha, 0.999)) * kSplatScale + 0.5);
  ivec3 nn = ivec3(round(alpha * normal * kSplatScale));
  v[3] = uint(nn.x);
  v[4] = uint(nn.y);
  v[5] = uint(nn.z);
  return true;
}

// The particle buffers' values from a pixel's sums: alpha is "over"'s,
// 1 - prod(1 - alpha_i); colour and normal are alpha-weighted means times it.
void resolveSplat(uint sums[kSplatChannels], out vec4 color, out vec4 normal) {
  color = vec4(0.0);
  normal = vec4(0.0);
  float weight = float(sums[0]);
  if (weight <= 0.0) return;
  float alpha = 1.0 - exp(-float(sums[2]) / kSplatScale);
  float age = float(sums[1]) / weight;  // alpha-weighted mean age: the mean colour, colour being linear in age
  color = vec4(mix(look.colorBirth.rgb, look.colorDeath.rgb, age) * alpha, alpha);
  normal = vec4(vec3(int(sums[3]), int(sums[4]), int(sums[5])) / weight * alpha, alpha);
}
