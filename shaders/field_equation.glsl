// Analytic fields evaluated in the shader (FIELD_EQUATION programs): the GLSL
// twins of the evaluate() functions of core/field (vortex, gravity point, wind,
// curl noise, sphere flow, downwash) and of GradientNoise, with the terms that
// core/field/field_equation.h packs. Not bitwise twins (sqrt, exp and pow
// differ between the CPU and a GPU): tests/contexts/field_equation_test.cpp
// bounds the difference.
#ifdef FIELD_EQUATION

const int kEquationTornado = 1, kEquationGravity = 2, kEquationWind = 3, kEquationCurlNoise = 4,
          kEquationSphereFlow = 5, kEquationDownwash = 6;
const int kMaxEquationTerms = 4;

struct EquationTerm {
  ivec4 kindSeed;  // kind, noise seed
  vec4 a, b, c;
};

layout(std140, binding = 3) uniform EquationBlock {
  ivec4 termCount;  // x
  EquationTerm terms[kMaxEquationTerms];
} equation;

#include "gradient_noise.glsl"

vec3 tornadoField(EquationTerm t, vec3 p) {
  vec3 d = p - t.a.xyz;
  vec3 axis = t.b.xyz;
  float along = dot(d, axis);
  if (along < 0.0 || along > t.b.w) return vec3(0.0);
  vec3 radial = d - along * axis;
  float rho = length(radial);
  float range = t.a.w;
  float falloff = clamp((range - rho) / range, 0.0, 1.0);
  if (falloff <= 0.0) return vec3(0.0);
  float scale = max(rho, t.c.x);
  vec3 outward = scale > 0.0 ? radial / scale : vec3(0.0);
  vec3 around = cross(axis, outward);
  return falloff * (t.c.y * around - t.c.z * outward + t.c.w * axis);
}

vec3 gravityField(EquationTerm t, vec3 p) {
  vec3 d = t.a.xyz - p;
  float distance = length(d);
  if (distance <= 0.0) return vec3(0.0);
  float percent = clamp((t.a.w - distance) / t.a.w, 0.0, 1.0);
  return d * (t.b.x * percent / distance);
}

vec3 windField(EquationTerm t, vec3 p) {
  vec3 v = t.a.w * t.a.xyz;
  if (t.b.x > 0.0) {
    vec3 q = p / t.b.y;
    uint seed = uint(t.kindSeed.y);
    v += t.b.x * vec3(noiseValueAndGradient(seed, q).w, noiseValueAndGradient(seed + 1u, q).w,
                      noiseValueAndGradient(seed + 2u, q).w);
  }
  return v;
}

vec3 curlNoiseField(EquationTerm t, vec3 p) {
  vec3 q = (p + t.a.xyz) / t.a.w;
  uint seed = uint(t.kindSeed.y);
  vec3 g1 = noiseValueAndGradient(seed, q).xyz;
  vec3 g2 = noiseValueAndGradient(seed + 1u, q).xyz;
  vec3 g3 = noiseValueAndGradient(seed + 2u, q).xyz;
  return t.b.x * vec3(g3.y - g2.z, g1.z - g3.x, g2.x - g1.y);
}

vec3 sphereFlowField(EquationTerm t, vec3 p) {
  vec3 x = p - t.a.xyz;
  float r2 = dot(x, x);
  float R = t.a.w;
  if (r2 < R * R) return vec3(0.0);
  float r = sqrt(r2);
  float r3 = r2 * r, r5 = r3 * r2;
  float halfR3 = 0.5 * R * R * R;
  vec3 U = t.b.xyz;
  vec3 v = U + halfR3 * (U / r3 - (3.0 * dot(U, x) / r5) * x);
  if (t.b.w != 0.0) {
    float e2 = t.c.x * t.c.x;
    float d = pow(r2 + e2, 1.5);
    v += (t.b.w / (4.0 * 3.14159265358979)) * x / d;
  }
  return v;
}

vec3 downwashField(EquationTerm t, vec3 p) {
  vec3 hub = t.a.xyz;
  float R = t.a.w, vh = t.b.x, flow = t.b.y, ground = t.b.z, layer = t.b.w;
  vec2 radial = p.xy - hub.xy;
  float r = length(radial);
  vec2 outward = r > 0.0 ? radial / r : vec2(0.0);
  float height = p.z - ground;
  if (height < 0.0) return vec3(0.0);
  float s = hub.z - p.z;
  float root = sqrt(s * s + R * R);
  float W = vh * (1.0 + s / root);
  float dW = vh * R * R / (root * root * root);
  vec3 v = vec3(0.0);
  if (W > 1e-12 * vh) {
    float a2 = R * R * vh / W;
    float profile = exp(-r * r / a2);
    float x = clamp(height / layer, 0.0, 1.0);
    float fade = x * x * (3.0 - 2.0 * x);
    float ur = -0.5 * dW * r * profile;
    v += fade * vec3(ur * outward, -W * profile);
  }
  float sg = hub.z - ground;
  float Wg = vh * (1.0 + sg / sqrt(sg * sg + R * R));
  float ag2 = R * R * vh / Wg;
  if (r > 0.0) {
    float delta = 0.1 * R + 0.05 * r;
    float eta = height / delta;
    float peak = flow / (2.0 * 3.14159265358979 * r * delta * 2.718281828459045);
    float ramp = 1.0 - exp(-r * r / ag2);
    v += vec3(peak * eta * exp(1.0 - eta) * ramp * outward, 0.0);
  }
  return v;
}

// The field in its own coordinates: the sum of the terms.
vec3 equationAt(vec3 p) {
  vec3 v = vec3(0.0);
  for (int i = 0; i < equation.termCount.x; ++i) {
    EquationTerm t = equation.terms[i];
    int kind = t.kindSeed.x;
    if (kind == kEquationTornado)
      v += tornadoField(t, p);
    else if (kind == kEquationGravity)
      v += gravityField(t, p);
    else if (kind == kEquationWind)
      v += windField(t, p);
    else if (kind == kEquationCurlNoise)
      v += curlNoiseField(t, p);
    else if (kind == kEquationSphereFlow)
      v += sphereFlowField(t, p);
    else if (kind == kEquationDownwash)
      v += downwashField(t, p);
  }
  return v;
}

#endif  // FIELD_EQUATION
