// Obstacles: the twin of core/obstacles/obstacle_physics.cpp, operation for
// operation, all `precise`. Needs sim_block.glsl and terrain_height.glsl.
// Included only by OBSTACLES programs: the obstacles' code takes registers
// that the update needs even when none is there (an H100's update at 10^7
// went from 0.76 to 1.09 ms with it compiled in and unused). The block's
// fields are read where they are used: a copy of an ObstacleBlock would hold
// sixteen registers.

const int kObstacleSphere = 0, kObstacleBox = 1, kObstacleCylinder = 2;
const float kObstacleMargin = 1e-4;

float obstacleSign(float x) {
  return x < 0.0 ? -1.0 : 1.0;
}

float dot3(vec3 a, vec3 b) {
  precise float d = a.x * b.x + a.y * b.y + a.z * b.z;
  return d;
}

// The signed distance to obstacle i's surface (negative inside); `normal`: the outward normal.
float obstacleSurface(int i, vec3 x, out vec3 normal) {
  precise vec3 d = x - sim.obstacles[i].positionRadius.xyz;
  normal = vec3(0.0, 0.0, 1.0);
  if (sim.obstacles[i].shapeFlow.x == kObstacleSphere) {
    precise float r = sqrt(dot3(d, d));
    if (r > 0.0) normal = d / r;
    precise float distance = r - sim.obstacles[i].positionRadius.w;
    return distance;
  }
  if (sim.obstacles[i].shapeFlow.x == kObstacleBox) {
    precise vec3 q = abs(d) - sim.obstacles[i].halfSize.xyz;
    if (q.x > 0.0 || q.y > 0.0 || q.z > 0.0) {
      vec3 m = max(q, vec3(0.0));
      precise float length = sqrt(dot3(m, m));
      precise vec3 n = vec3(obstacleSign(d.x), obstacleSign(d.y), obstacleSign(d.z)) * (m / length);
      normal = n;
      return length;
    }
    int axis = 0;
    if (q.y > q[axis]) axis = 1;
    if (q.z > q[axis]) axis = 2;
    normal = vec3(0.0);
    normal[axis] = obstacleSign(d[axis]);
    return q[axis];
  }
  precise float rho = sqrt(d.x * d.x + d.y * d.y);
  vec3 radial = vec3(1.0, 0.0, 0.0);
  if (rho > 0.0) {
    precise vec3 r = vec3(d.x / rho, d.y / rho, 0.0);
    radial = r;
  }
  precise float qr = rho - sim.obstacles[i].positionRadius.w;
  precise float qz = abs(d.z) - sim.obstacles[i].halfSize.w;
  vec3 up = vec3(0.0, 0.0, obstacleSign(d.z));
  if (qr > 0.0 || qz > 0.0) {
    float mr = max(qr, 0.0), mz = max(qz, 0.0);
    precise float length = sqrt(mr * mr + mz * mz);
    precise vec3 n = (mr / length) * radial + (mz / length) * up;
    normal = n;
    return length;
  }
  normal = qr > qz ? radial : up;
  return max(qr, qz);
}

// A box's or cylinder's boundary layer: its smallest half-extent.
float obstacleLayer(int i) {
  if (sim.obstacles[i].shapeFlow.x == kObstacleBox) return min(min(sim.obstacles[i].halfSize.x, sim.obstacles[i].halfSize.y), sim.obstacles[i].halfSize.z);
  return min(sim.obstacles[i].positionRadius.w, sim.obstacles[i].halfSize.w);
}

// Whether x is certainly at least `layer` outside a box's or cylinder's
// surface (beyondLayer in the C++).
bool beyondLayer(int i, vec3 x, float layer) {
  precise vec3 d = abs(x - sim.obstacles[i].positionRadius.xyz);
  if (sim.obstacles[i].shapeFlow.x == kObstacleBox) {
    precise vec3 q = d - sim.obstacles[i].halfSize.xyz;
    return q.x >= layer || q.y >= layer || q.z >= layer;
  }
  precise float reach = sim.obstacles[i].positionRadius.w + layer;
  precise float qz = d.z - sim.obstacles[i].halfSize.w;
  precise float rho2 = d.x * d.x + d.y * d.y;
  precise float reach2 = reach * reach;
  return qz >= layer || rho2 >= reach2;
}

// Whether x is certainly outside obstacle i (clearOf in the C++).
bool clearOf(int i, vec3 x) {
  precise vec3 d = x - sim.obstacles[i].positionRadius.xyz;
  if (sim.obstacles[i].shapeFlow.x == kObstacleBox) {
    precise vec3 q = abs(d) - sim.obstacles[i].halfSize.xyz;
    return q.x >= 0.0 || q.y >= 0.0 || q.z >= 0.0;
  }
  precise float r = 1.001 * sim.obstacles[i].positionRadius.w;
  precise float r2 = r * r;
  if (sim.obstacles[i].shapeFlow.x == kObstacleSphere) return dot3(d, d) >= r2;
  precise float qz = abs(d.z) - sim.obstacles[i].halfSize.w;
  precise float rho2 = d.x * d.x + d.y * d.y;
  return qz >= 0.0 || rho2 >= r2;
}

// The height at which x's column leaves obstacle i upwards.
float obstacleTop(int i, vec3 x) {
  if (sim.obstacles[i].shapeFlow.x == kObstacleBox) {
    precise float top = sim.obstacles[i].positionRadius.z + sim.obstacles[i].halfSize.z;
    return top;
  }
  if (sim.obstacles[i].shapeFlow.x == kObstacleCylinder) {
    precise float top = sim.obstacles[i].positionRadius.z + sim.obstacles[i].halfSize.w;
    return top;
  }
  precise float dx = x.x - sim.obstacles[i].positionRadius.x, dy = x.y - sim.obstacles[i].positionRadius.y;
  precise float across = max(sim.obstacles[i].positionRadius.w * sim.obstacles[i].positionRadius.w - (dx * dx + dy * dy), 0.0);
  precise float top = sim.obstacles[i].positionRadius.z + sqrt(across);
  return top;
}

vec3 flowAroundObstacles(vec3 f, vec3 x, bool velocityField) {
  precise vec3 result = f;
  for (int i = 0; i < sim.obstacleCount.x; ++i) {
    if (sim.obstacles[i].shapeFlow.y == 0) continue;
    precise vec3 u = velocityField ? f - sim.obstacles[i].velocity.xyz : f;
    if (sim.obstacles[i].shapeFlow.x == kObstacleSphere) {
      precise vec3 d = x - sim.obstacles[i].positionRadius.xyz;
      precise float r = sqrt(dot3(d, d));
      if (!(r > 0.0)) continue;
      precise vec3 n = d * (1.0 / r);
      float rc = max(r, sim.obstacles[i].positionRadius.w);
      precise float k = sim.obstacles[i].halfSize.x / (rc * rc * rc);  // R^3 / 2 over rc^3
      precise float un = dot3(u, n);
      result = result + k * (u - (3.0 * un) * n);
      continue;
    }
    float layer = obstacleLayer(i);
    if (beyondLayer(i, x, layer)) continue;
    vec3 normal;
    float distance = obstacleSurface(i, x, normal);
    if (!(distance < layer)) continue;
    precise float t = clamp(distance / layer, 0.0, 1.0);
    precise float w = 1.0 - t * t * (3.0 - 2.0 * t);
    precise float un = dot3(u, normal);
    result = result - (w * un) * normal;
  }
  return result;
}

// After a step: out of obstacle i onto its surface, bouncing off it; with
// `ground`, leaving it straight up where the nearest point is under the terrain.
bool pushOutOfObstacle(int i, inout vec3 x, inout vec3 v, bool ground) {
  if (clearOf(i, x)) return false;
  vec3 n;
  float distance = obstacleSurface(i, x, n);
  if (!(distance < 0.0)) return false;
  precise vec3 y = x + (kObstacleMargin - distance) * n;
  if (ground && y.z < terrainHeight(y.xy)) {
    precise float top = obstacleTop(i, x) + kObstacleMargin;
    y = vec3(x.x, x.y, top);
    n = vec3(0.0, 0.0, 1.0);
  }
  x = y;
  precise float vn = dot3(v - sim.obstacles[i].velocity.xyz, n);
  if (vn < 0.0) {
    precise vec3 bounced = v - ((1.0 + sim.obstacles[i].velocity.w) * vn) * n;
    v = bounced;
  }
  return true;
}

// Out of every obstacle (keepOutOfObstacles): pushes, then straight up out
// of any a push landed in.
void keepOutOfObstacles(inout vec3 x, inout vec3 v, bool ground) {
  bool pushed = false;
  for (int i = 0; i < sim.obstacleCount.x; ++i)
    if (pushOutOfObstacle(i, x, v, ground)) pushed = true;
  if (!pushed) return;
  for (int pass = 0; pass < sim.obstacleCount.x; ++pass) {
    bool rose = false;
    for (int i = 0; i < sim.obstacleCount.x; ++i) {
      vec3 n;
      if (clearOf(i, x) || !(obstacleSurface(i, x, n) < 0.0)) continue;
      precise float top = obstacleTop(i, x) + kObstacleMargin;
      x.z = top;
      rose = true;
    }
    if (!rose) return;
  }
}

// A newborn particle out of every obstacle (settleNewborn in particle_physics.cpp).
void settleNewborn(inout Particle p) {
  if (sim.obstacleCount.x == 0) return;
  vec3 x = p.positionLife.xyz, v = p.velocityKind.xyz;
  keepOutOfObstacles(x, v, sim.modes.w != 0 && sim.terrainDims.z != 0);
  p.positionLife.xyz = x;
  p.velocityKind.xyz = v;
}
