// Motion blur (render.shutter, thesis 7.2): a particle is drawn where it was
// while the shutter was open. Its puff's centre moved from -m to 0 (in units
// of its radius, in the plane it is drawn in); what covers point p is the
// puff's falloff (1 - d^2)^2 averaged over that time (a box shutter),
// integrated in closed form along the path, so a smear keeps the particle's
// total opacity and is as long as its path plus its diameter. Lumps as the
// sprite's (core/light/puff_sprite.cpp), taken at the nearest point of the path.

float puffLumps(vec2 c) {
  return 0.8 + 0.2 * sin(9.0 * c.x + 3.0 * sin(7.0 * c.y)) * cos(8.0 * c.y);
}

// The time-averaged falloff at p; `closest`: p relative to the nearest centre
// on the path (for the sphere's normal and the lumps).
float smearedPuff(vec2 p, vec2 m, out vec2 closest) {
  float len = length(m);
  float t = len > 0.0 ? clamp(dot(p + m, m) / (len * len), 0.0, 1.0) : 1.0;
  closest = p + m - t * m;
  if (len < 1e-4) {
    float f = max(1.0 - dot(p, p), 0.0);
    return f * f;
  }
  vec2 a = m / len;
  vec2 q = p + 0.5 * m;  // from the path's midpoint
  float u = dot(q, a), v = dot(q, vec2(-a.y, a.x)), h = 0.5 * len;
  float w2 = 1.0 - v * v;
  if (w2 <= 0.0) return 0.0;
  float w = sqrt(w2);
  float z0 = max(u - h, -w), z1 = min(u + h, w);
  if (z1 <= z0) return 0.0;
  // The integral of (w^2 - z^2)^2 dz.
  float f1 = w2 * w2 * z1 - 2.0 * w2 * z1 * z1 * z1 / 3.0 + z1 * z1 * z1 * z1 * z1 / 5.0;
  float f0 = w2 * w2 * z0 - 2.0 * w2 * z0 * z0 * z0 / 3.0 + z0 * z0 * z0 * z0 * z0 / 5.0;
  return (f1 - f0) / len;
}
