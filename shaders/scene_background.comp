#version 450 core
// SceneBackground: after the raster scene items (props, lines, a height
// map's terrain), each pixel's flat ground or sky where no item lies in
// front of it, and the scene's depth (window depth, 1 at the far plane) for
// the passes after: the items' where they are nearer, the ground's, or 1.
// On datacenter GPUs the raster pipeline fills pixels slowly (the ground and
// sky took 0.2-0.3 ms a 1920x1080 view on an H100); compute does not.
#include "view_block.glsl"
#include "render_block.glsl"
#include "shadow_block.glsl"
#include "scene_ground.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 3) uniform sampler2D uItemsDepth;  // the raster items' depth buffer
layout(rgba8, binding = 0) writeonly uniform image2D uColor;
layout(r32f, binding = 1) writeonly uniform image2D uDepth;
layout(location = 0) uniform vec4 uGroundBounds;  // xy: least x, y; zw: greatest
layout(location = 1) uniform float uGroundHeight;
layout(location = 2) uniform bool uFlatGround;     // false: no ground here (a height map's is raster)
layout(location = 3) uniform bool uItems;          // false: no raster items were drawn (depth 1)
// Lines (the field's box): window x, y (pixels) and depth of each end.
const int kMaxLines = 12;
layout(location = 4) uniform int uLineCount;
layout(location = 5) uniform vec3 uLineColor;
layout(location = 6) uniform vec3 uLineA[kMaxLines];
layout(location = 18) uniform vec3 uLineB[kMaxLines];

// The point where the eye's ray through window position `pixel` meets the
// ground plane, and its window depth; false where it does not (looking away,
// beyond the ground's bounds, or outside the near and far planes).
bool groundAt(vec2 pixel, out vec3 point, out float depth) {
  vec2 ndc = pixel / view.viewport.zw * 2.0 - 1.0;
  vec4 far = view.inverseViewProjection * vec4(ndc, 1.0, 1.0);
  vec3 dir = far.xyz / far.w - view.eye.xyz;
  if (abs(dir.z) < 1e-12) return false;
  float t = (uGroundHeight - view.eye.z) / dir.z;
  if (t <= 0.0) return false;
  point = view.eye.xyz + t * dir;
  if (any(lessThan(point.xy, uGroundBounds.xy)) || any(greaterThan(point.xy, uGroundBounds.zw))) return false;
  vec4 clip = view.viewProjection * vec4(point, 1.0);
  if (clip.w <= 0.0) return false;
  depth = clip.z / clip.w * 0.5 + 0.5;
  return depth >= 0.0 && depth <= 1.0;
}

// The window depth of the nearest line covering the pixel centred at `c`, as
// GL rasterises a one-pixel line (the pixel of each column a mostly
// horizontal line crosses, of each row for a mostly vertical one); 2 where
// no line covers it.
float lineDepth(vec2 c) {
  float nearest = 2.0;
  for (int i = 0; i < uLineCount; ++i) {
    vec3 a = uLineA[i], b = uLineB[i];
    vec2 d = b.xy - a.xy;
    bool xMajor = abs(d.x) >= abs(d.y);
    float major = xMajor ? d.x : d.y;
    if (abs(major) < 1e-6) continue;
    float t = ((xMajor ? c.x : c.y) - (xMajor ? a.x : a.y)) / major;
    if (t < 0.0 || t >= 1.0) continue;
    vec2 on = a.xy + t * d;
    float off = xMajor ? c.y - on.y : c.x - on.x;
    if (off <= -0.5 || off > 0.5) continue;
    nearest = min(nearest, mix(a.z, b.z, t));
  }
  return nearest;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(view.viewport.z) || p.y >= int(view.viewport.w)) return;
  float items = uItems ? texelFetch(uItemsDepth, p, 0).r : 1.0;
  vec2 centre = vec2(p) + 0.5;
  // A line in front of every raster item is drawn as one of them would be.
  float line = uLineCount > 0 ? lineDepth(centre) : 2.0;
  bool lineInFront = line < items;
  items = min(items, line);
  if (lineInFront) imageStore(uColor, p, vec4(uLineColor, 1.0));
  vec3 point;
  float ground;
  if (uFlatGround && groundAt(centre, point, ground)) {
    if (items < ground) {  // an item in front (as GL_LESS after the ground)
      imageStore(uDepth, p, vec4(items));
      return;
    }
    // The grid lines' width: the ground's step to the next pixel across and
    // up (the neighbour's ray may miss the plane at the horizon: no lines).
    vec3 across, up;
    float unused;
    vec2 width = vec2(1e6);
    if (groundAt(centre + vec2(1.0, 0.0), across, unused) && groundAt(centre + vec2(0.0, 1.0), up, unused))
      width = abs(across.xy - point.xy) + abs(up.xy - point.xy);
    imageStore(uColor, p, vec4(groundColor(point, vec3(0.0, 0.0, 1.0), width), 1.0));
    imageStore(uDepth, p, vec4(ground));
    return;
  }
  imageStore(uDepth, p, vec4(items));
  if (items < 1.0) return;
  vec4 far = view.inverseViewProjection * vec4(centre / view.viewport.zw * 2.0 - 1.0, 1.0, 1.0);
  imageStore(uColor, p, vec4(skyColor(normalize(far.xyz / far.w - view.eye.xyz)), 1.0));
}
