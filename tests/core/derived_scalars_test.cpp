// Derived quantities against flows whose gradients are known by hand: solid
// rotation, pure strain, uniform expansion and a helical flow. Central
// differences are exact for linear fields, so every point must match.
#include "core/field/derived_scalars.h"

#include <gtest/gtest.h>

#include <functional>

#include "core/util/error.h"

namespace sandstorm {
namespace {

VectorField sampled(const std::function<glm::vec3(glm::vec3)>& v) {
  VectorField f(Box{{-2, -1, 0}, {2, 1, 1}}, {5, 3, 3});
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 5; ++i)
        f.at(i, j, k) = v(f.pointPosition(i, j, k));
  return f;
}

void expectEverywhere(const VectorField& f, const char* name,
                      const std::function<float(glm::vec3)>& want) {
  const VectorField::Scalars s = derivedScalars(f, name);
  EXPECT_EQ(s.name, name);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 5; ++i)
        ASSERT_NEAR(s.values[f.index(i, j, k)], want(f.pointPosition(i, j, k)), 1e-5f)
            << name << " at " << i << " " << j << " " << k;
}

TEST(DerivedScalars, SolidRotationIsAllRotation) {
  const float w = 1.5f;  // v = w (-y, x, 0): curl (0, 0, 2w), Q = w^2
  const VectorField f = sampled([&](glm::vec3 p) { return w * glm::vec3(-p.y, p.x, 0.0f); });
  expectEverywhere(f, "vorticity", [&](glm::vec3) { return 2.0f * w; });
  expectEverywhere(f, "divergence", [](glm::vec3) { return 0.0f; });
  expectEverywhere(f, "q_criterion", [&](glm::vec3) { return w * w; });
  expectEverywhere(f, "helicity", [](glm::vec3) { return 0.0f; });
  expectEverywhere(f, "speed", [&](glm::vec3 p) { return w * glm::length(glm::vec2(p)); });
}

TEST(DerivedScalars, PureStrainHasNegativeQAndExpansionItsDivergence) {
  const float a = 2.0f;  // v = a (x, -y, 0): S = diag(a, -a, 0), Q = -a^2
  expectEverywhere(sampled([&](glm::vec3 p) { return a * glm::vec3(p.x, -p.y, 0.0f); }),
                   "q_criterion", [&](glm::vec3) { return -a * a; });
  expectEverywhere(sampled([](glm::vec3 p) { return 0.5f * p; }), "divergence",
                   [](glm::vec3) { return 1.5f; });
}

TEST(DerivedScalars, HelicityOfAHelicalFlow) {
  // v = (-y, x, c): curl (0, 0, 2), helicity 2c.
  const float c = 0.75f;
  expectEverywhere(sampled([&](glm::vec3 p) { return glm::vec3(-p.y, p.x, c); }), "helicity",
                   [&](glm::vec3) { return 2.0f * c; });
}

TEST(DerivedScalars, AnUnknownNameIsRefusedWithTheList) {
  try {
    derivedScalars(sampled([](glm::vec3 p) { return p; }), "lambda2");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'lambda2'; expected one of: speed, vorticity"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sandstorm
