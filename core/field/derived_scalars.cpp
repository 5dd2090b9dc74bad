#include "core/field/derived_scalars.h"

#include <array>
#include <string>

#include "core/field/velocity_gradient.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr std::array<std::string_view, 5> kNames = {"speed", "vorticity", "divergence",
                                                    "q_criterion", "helicity"};

float derive(std::string_view name, const glm::vec3& v, const glm::mat3& g) {
  if (name == "speed") return glm::length(v);
  if (name == "divergence") return g[0].x + g[1].y + g[2].z;
  const glm::vec3 curl(g[1].z - g[2].y, g[2].x - g[0].z, g[0].y - g[1].x);
  if (name == "vorticity") return glm::length(curl);
  if (name == "helicity") return glm::dot(v, curl);
  // q_criterion: |W|^2 - |S|^2 over two, from J = g (symmetric in the norms).
  float w2 = 0.0f, s2 = 0.0f;
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {
      const float s = 0.5f * (g[a][c] + g[c][a]), w = 0.5f * (g[a][c] - g[c][a]);
      s2 += s * s;
      w2 += w * w;
    }
  return 0.5f * (w2 - s2);
}

}  // namespace

std::span<const std::string_view> derivedScalarNames() {
  return kNames;
}

VectorField::Scalars derivedScalars(const VectorField& field, std::string_view name) {
  bool known = false;
  std::string list;
  for (std::string_view n : kNames) {
    known = known || n == name;
    list += (list.empty() ? "" : ", ") + std::string(n);
  }
  if (!known) throw Error(concat("no derived quantity '", name, "'; expected one of: ", list));
  VectorField::Scalars out{std::string(name), std::vector<float>(field.pointCount(), 0.0f)};
  const glm::ivec3 d = field.dims();
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i)
        if (field.valid(i, j, k))
          out.values[field.index(i, j, k)] =
              derive(name, field.at(i, j, k), velocityGradient(field, {i, j, k}));
  return out;
}

}  // namespace sandstorm
