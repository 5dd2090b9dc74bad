// The helicopter the scene draws (core/props/helicopter_model.h): closed,
// outward-facing surfaces, and its solid-looking parts inside the boxes the
// dust collides with (core/obstacles/helicopter_shape.h), so the picture does
// not show dust passing through a fuselage.
#include "core/props/helicopter_model.h"

#include <gtest/gtest.h>

#include "core/obstacles/helicopter_shape.h"

namespace sandstorm {
namespace {

TEST(HelicopterModel, EveryTriangleFacesOutAndTheBodyLiesInsideTheSolidBoxes) {
  const float r = 7.0f;
  const std::vector<ModelPart> parts = helicopterModel(r);
  std::vector<HelicopterPart> solid;
  for (const HelicopterPart& p : helicopterParts(r))
    if (p.role == HelicopterPart::Role::Body) solid.push_back(p);
  int translucent = 0;
  for (const ModelPart& part : parts) {
    SCOPED_TRACE(part.name);
    ASSERT_FALSE(part.triangles.empty());
    ASSERT_EQ(part.triangles.size() % 3, 0u);
    if (part.color.w < 1.0f) ++translucent;
    for (std::size_t i = 0; i < part.triangles.size(); i += 3) {
      const ModelVertex &a = part.triangles[i], &b = part.triangles[i + 1],
                        &c = part.triangles[i + 2];
      for (const ModelVertex* v : {&a, &b, &c})
        EXPECT_NEAR(glm::length(v->normal), 1.0f, 1e-4f);
      const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
      if (glm::length(face) > 1e-6f) {  // counter-clockwise seen from where the normals point
        EXPECT_GT(glm::dot(face, a.normal + b.normal + c.normal), 0.0f) << "triangle " << i / 3;
      }
    }
    if (part.name != "body" && part.name != "glazing") continue;
    for (const ModelVertex& v : part.triangles) {
      bool inside = false;
      for (const HelicopterPart& box : solid)
        inside = inside || glm::all(glm::lessThanEqual(glm::abs(v.position - box.center),
                                                       0.5f * box.size + 1e-4f * r));
      EXPECT_TRUE(inside) << v.position.x << " " << v.position.y << " " << v.position.z;
      if (!inside) break;
    }
  }
  EXPECT_EQ(translucent, 2);  // the main and tail rotors' blur
}

}  // namespace
}  // namespace sandstorm
