#include "core/props/helicopter_model.h"

#include <cmath>

#include <glm/gtc/constants.hpp>

namespace sandstorm {
namespace {

using Triangles = std::vector<ModelVertex>;

// A quad a, b, c, d (counter-clockwise seen from outside) with its vertices' normals.
void quad(Triangles& t, const ModelVertex& a, const ModelVertex& b, const ModelVertex& c,
          const ModelVertex& d) {
  t.insert(t.end(), {a, b, c, a, c, d});
}

// An ellipsoid: the unit sphere scaled by `radii` about `centre` (normals
// through the inverse scale, so the shading follows the stretched surface).
void ellipsoid(Triangles& t, glm::vec3 centre, glm::vec3 radii, int slices = 40, int stacks = 20) {
  const auto at = [&](int i, int j) {
    const float theta = glm::pi<float>() * float(j) / float(stacks);
    const float phi = glm::two_pi<float>() * float(i) / float(slices);
    const glm::vec3 u(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                      std::cos(theta));
    return ModelVertex{centre + radii * u, glm::normalize(u / radii)};
  };
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i)
      quad(t, at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
}

// A frustum from `a` (radius ra) to `b` (radius rb), capped at both ends.
void frustum(Triangles& t, glm::vec3 a, glm::vec3 b, float ra, float rb, int segments = 24) {
  const glm::vec3 axis = glm::normalize(b - a);
  const glm::vec3 u = glm::normalize(
      glm::cross(std::abs(axis.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0), axis));
  const glm::vec3 v = glm::cross(axis, u);
  const float slope = (ra - rb) / glm::length(b - a);  // the side's normal leans along the axis
  for (int i = 0; i < segments; ++i) {
    const float p0 = glm::two_pi<float>() * float(i) / float(segments);
    const float p1 = glm::two_pi<float>() * float(i + 1) / float(segments);
    const glm::vec3 r0 = std::cos(p0) * u + std::sin(p0) * v,
                    r1 = std::cos(p1) * u + std::sin(p1) * v;
    const glm::vec3 n0 = glm::normalize(r0 + slope * axis), n1 = glm::normalize(r1 + slope * axis);
    quad(t, {a + ra * r0, n0}, {a + ra * r1, n1}, {b + rb * r1, n1}, {b + rb * r0, n0});
    t.insert(t.end(), {{b, axis}, {b + rb * r0, axis}, {b + rb * r1, axis}});
    t.insert(t.end(), {{a, -axis}, {a + ra * r1, -axis}, {a + ra * r0, -axis}});
  }
}

// An axis-aligned box.
void box(Triangles& t, glm::vec3 centre, glm::vec3 size) {
  const glm::vec3 h = 0.5f * size;
  for (int axis = 0; axis < 3; ++axis)
    for (const float side : {-1.0f, 1.0f}) {
      glm::vec3 n(0.0f);
      n[axis] = side;
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      glm::vec3 e1(0.0f), e2(0.0f);
      e1[a] = h[a];
      e2[b] = h[b];
      const glm::vec3 c = centre + n * h[axis];
      // Counter-clockwise seen from outside: e1 x e2 points along +axis.
      if (side > 0.0f)
        quad(t, {c - e1 - e2, n}, {c + e1 - e2, n}, {c + e1 + e2, n}, {c - e1 + e2, n});
      else
        quad(t, {c - e1 - e2, n}, {c - e1 + e2, n}, {c + e1 + e2, n}, {c + e1 - e2, n});
    }
}

// A disc of radius r about `centre`, facing both ways along `normal` (seen from above and below).
void disc(Triangles& t, glm::vec3 centre, glm::vec3 normal, float r, int segments = 64) {
  const glm::vec3 n = glm::normalize(normal);
  const glm::vec3 u =
      glm::normalize(glm::cross(std::abs(n.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0), n));
  const glm::vec3 v = glm::cross(n, u);
  for (int i = 0; i < segments; ++i) {
    const float p0 = glm::two_pi<float>() * float(i) / float(segments);
    const float p1 = glm::two_pi<float>() * float(i + 1) / float(segments);
    const glm::vec3 a = centre + r * (std::cos(p0) * u + std::sin(p0) * v);
    const glm::vec3 b = centre + r * (std::cos(p1) * u + std::sin(p1) * v);
    t.insert(t.end(), {{centre, n}, {a, n}, {b, n}, {centre, -n}, {b, -n}, {a, -n}});
  }
}

}  // namespace

std::vector<ModelPart> helicopterModel(float r) {
  // Olive-drab livery, dark against the light dust it raises; darker metal,
  // tinted glazing.
  const glm::vec4 livery(0.3f, 0.34f, 0.2f, 1.0f), metal(0.16f, 0.16f, 0.17f, 1.0f),
      glass(0.16f, 0.24f, 0.3f, 1.0f);
  ModelPart body{"body", livery, {}}, dark{"metal", metal, {}}, glazing{"glazing", glass, {}},
      stabiliser{"stabiliser", livery, {}};
  // Fuselage and cowling: within the solid box centred (0.1, 0, -0.33) r, 1.6 x 0.34 x 0.32 r.
  ellipsoid(body.triangles, glm::vec3(0.08f, 0.0f, -0.34f) * r, glm::vec3(0.72f, 0.16f, 0.15f) * r);
  ellipsoid(body.triangles, glm::vec3(-0.05f, 0.0f, -0.235f) * r,
            glm::vec3(0.34f, 0.1f, 0.06f) * r);
  // The cockpit's glazing wraps the nose, forward and up.
  ellipsoid(glazing.triangles, glm::vec3(0.42f, 0.0f, -0.3f) * r,
            glm::vec3(0.34f, 0.145f, 0.12f) * r);
  // Tail boom, tapering aft to the fin (within the boom's and fin's boxes).
  frustum(body.triangles, glm::vec3(-0.55f, 0.0f, -0.21f) * r, glm::vec3(-1.92f, 0.0f, -0.175f) * r,
          0.04f * r, 0.022f * r);
  box(body.triangles, glm::vec3(-1.9f, 0.0f, -0.06f) * r, glm::vec3(0.12f, 0.02f, 0.3f) * r);
  box(stabiliser.triangles, glm::vec3(-1.55f, 0.0f, -0.19f) * r,
      glm::vec3(0.1f, 0.32f, 0.012f) * r);
  // Skids on struts under the fuselage.
  for (const float side : {-1.0f, 1.0f}) {
    frustum(dark.triangles, glm::vec3(-0.45f, side * 0.2f, -0.56f) * r,
            glm::vec3(0.55f, side * 0.2f, -0.56f) * r, 0.014f * r, 0.014f * r, 12);
    for (const float x : {-0.25f, 0.3f})
      frustum(dark.triangles, glm::vec3(x, side * 0.2f, -0.56f) * r,
              glm::vec3(x, side * 0.1f, -0.45f) * r, 0.01f * r, 0.01f * r, 8);
  }
  // Mast and hub.
  frustum(dark.triangles, glm::vec3(0.0f, 0.0f, -0.17f) * r, glm::vec3(0.0f, 0.0f, 0.0f), 0.03f * r,
          0.025f * r, 16);
  ellipsoid(dark.triangles, glm::vec3(0.0f), glm::vec3(0.07f, 0.07f, 0.03f) * r, 16, 8);
  // The rotors as their blades' blur: a faint disc each.
  ModelPart rotor{"main rotor", glm::vec4(0.12f, 0.12f, 0.13f, 0.28f), {}};
  disc(rotor.triangles, glm::vec3(0.0f, 0.0f, 0.005f * r), glm::vec3(0, 0, 1), r);
  ModelPart tailRotor{"tail rotor", glm::vec4(0.12f, 0.12f, 0.13f, 0.3f), {}};
  disc(tailRotor.triangles, glm::vec3(-1.9f, 0.03f, -0.05f) * r, glm::vec3(0, 1, 0), 0.17f * r, 32);
  return {body, glazing, stabiliser, dark, rotor, tailRotor};
}

}  // namespace sandstorm
