// ParticleSplat, trails: what trail_splat.comp (global atomics) and the tiled
// passes (trail_bin.comp, trail_tile.comp) share, so all three find the same
// pixels with the same values and add the same integers.
//
// Segment j of particle o's trail (j = 0 the newest) joins its positions j
// and j + 1 back from the newest; it is walked in n steps from its newer end, one pixel a step, n its
// longer axis in pixels (at most kTrailMaxPixels); a trail's pixels are
// numbered j * kTrailMaxPixels + step. Each adds to the splat sums
// (splat_common.glsl's channels) like a splat's pixel: alpha fading along the
// trail and behind the scene, weighed by its optical depth, and the
// particle's colour coordinate, in the trails' two channels
// (splat_common.glsl). The positions are `precise`, so that every program that
// includes this file puts a step on the same pixel.
//
// Needs view_block.glsl, render_block.glsl, splat_common.glsl, and a
// definition of trailAdd (below) in the including shader.
layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 1) readonly restrict buffer VelocityKind { vec4 velocityKind[]; };
layout(std430, binding = 15) readonly restrict buffer Ring { vec4 ring[]; };  // uTrailLength a record
layout(binding = 3) uniform sampler2D uSceneDepth;
layout(location = 16) uniform int uTrailLength;
layout(location = 17) uniform int uTrailHead;  // the ring's newest slot

const int kTrailMaxPixels = 64;  // a segment's pixels (one frame of motion: a few)

struct TrailSegment {
  vec2 pa, d;    // the newer end and the way to the older one, in view pixels
  float wa, wb;  // the ends' distances from the eye
  int j, n;      // the segment, and the steps it walks
};

struct TrailLook {
  float t, opacity;  // the colour map's coordinate and the opacity, of the particle now
};

TrailLook trailLook(uint o) {
  vec4 pl = positionLife[o], vk = velocityKind[o];
  precise float age = clamp(1.0 - pl.w / max(vk.w, 1e-6), 0.0, 1.0);
  precise float t = colorCoordinate(age, vk.xyz, pl.xyz), opacity = mix(look.colorBirth.a, look.colorDeath.a, age);
  return TrailLook(t, opacity);
}

// Position k back from the newest of particle o's trail, as the view sees it;
// a walk along a trail projects each once, for the two segments it ends.
struct TrailPoint {
  vec2 p;      // in view pixels
  float w;     // the distance from the eye
  bool valid;  // the slot holds a position, and it lies in front of the eye
};

TrailPoint trailPoint(uint o, int k) {
  vec4 x = ring[o * uint(uTrailLength) + uint((uTrailHead - k + uTrailLength) % uTrailLength)];
  precise vec4 c = view.viewProjection * vec4(x.xyz, 1.0);
  precise vec2 p = (c.xy / c.w * 0.5 + 0.5) * view.viewport.zw;
  return TrailPoint(p, c.w, x.w >= 0.5 && c.w > 1e-4);
}

// Segment j from its newer end a (position j back) to its older end b (j + 1);
// false where either end is missing or behind the eye.
bool trailSegment(TrailPoint a, TrailPoint b, int j, out TrailSegment s) {
  if (!a.valid || !b.valid) return false;
  precise vec2 d = b.p - a.p;
  s.pa = a.p;
  s.d = d;
  s.wa = a.w;
  s.wb = b.w;
  s.j = j;
  s.n = min(int(ceil(max(abs(d.x), abs(d.y)))), kTrailMaxPixels);
  return true;
}

bool trailSegment(uint o, int j, out TrailSegment s) {
  return trailSegment(trailPoint(o, j), trailPoint(o, j + 1), j, s);
}

// Where along the segment a step lies, 0 to 1 (the pixel at the older end belongs to the next segment).
float trailAlong(TrailSegment s, int step) {
  precise float u = (float(step) + 0.5) / float(max(s.n, 1));
  return u;
}

ivec2 trailPixel(TrailSegment s, int step) {
  precise vec2 p = s.pa + trailAlong(s, step) * s.d;
  return ivec2(floor(p));
}

bool trailOnScreen(ivec2 p) {
  return all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, ivec2(view.viewport.zw)));
}

// The sums a step adds at pixel p (on screen): its optical depth and the
// same times the colour coordinate, fixed point; false where it adds nothing.
bool trailValues(TrailSegment s, TrailLook l, int step, ivec2 p, out uint v[kSplatTrailChannels]) {
  // `precise` throughout: the atomic and the tiled passes are two programs
  // that must add the same integers (ParticleSplat picks either a view).
  float u = trailAlong(s, step);
  precise float distance = mix(s.wa, s.wb, u);
  precise float scene = viewDistance(texelFetch(uSceneDepth, p, 0).r);
  precise float fade = clamp((scene - distance) / max(look.params.y, 1e-4), 0.0, 1.0);
  precise float along = (float(s.j) + u) / float(uTrailLength - 1);
  precise float alpha = l.opacity * (1.0 - along) * fade;
  if (alpha < 1.0 / 512.0) return false;
  precise float opticalDepth = -log(1.0 - min(alpha, 0.999));
  precise float depth = opticalDepth * kSplatScale + 0.5, colour = opticalDepth * l.t * kSplatScale + 0.5;
  v[0] = uint(depth);
  v[1] = uint(colour);
  return true;
}

// Adds a pixel's sums where the including shader keeps them (origin: the tile's).
void trailAdd(ivec2 p, ivec2 origin, uint v[kSplatTrailChannels]);

// Adds the pixels first..last (trail pixel numbers) of particle o's trail
// that lie in the 32x32 tile at `origin`.
void trailRun(uint o, uint first, uint last, ivec2 origin) {
  TrailLook l = trailLook(o);
  int j0 = int(first) / kTrailMaxPixels, j1 = int(last) / kTrailMaxPixels;
  TrailPoint newer = trailPoint(o, j0);
  for (int j = j0; j <= j1; ++j) {
    TrailPoint older = trailPoint(o, j + 1);
    TrailSegment s;
    bool drawn = trailSegment(newer, older, j, s);
    newer = older;
    if (!drawn) continue;
    int from = j == j0 ? int(first) % kTrailMaxPixels : 0;
    int to = j == j1 ? min(int(last) % kTrailMaxPixels, s.n - 1) : s.n - 1;
    for (int step = from; step <= to; ++step) {
      ivec2 p = trailPixel(s, step);
      if (!trailOnScreen(p) || any(lessThan(p, origin)) || any(greaterThanEqual(p, origin + kSplatTile)))
        continue;
      uint v[kSplatTrailChannels];
      if (trailValues(s, l, step, p, v)) trailAdd(p, origin, v);
    }
  }
}
