#include "core/molecules/molecule_shape.h"

#include <cmath>

#include "core/molecules/molecule_settings.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

MoleculeShape makeShape(int n) {
  MoleculeShape s;
  s.members = n;
  if (n == 3) {
    // A dart: the head kDartLength in front of a base of 1.
    s.rest = {{kDartLength, 0, 0}, {0, 0.5f, 0}, {0, -0.5f, 0}};
    s.faces = {{0, 1, 2}};
  } else if (n == 4) {
    // A dart: the head kDartLength in front of an equilateral base of edge 1.
    const float r = 1.0f / std::sqrt(3.0f);
    s.rest = {{kDartLength, 0, 0}, {0, r, 0}, {0, -0.5f * r, 0.5f}, {0, -0.5f * r, -0.5f}};
    s.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  } else {
    // A rod (2) or a chain: along -x, one edge apart.
    for (int i = 0; i < n; ++i)
      s.rest.push_back({-float(i), 0, 0});
    for (int i = 0; i + 1 < n; ++i)
      s.lines.push_back({i, i + 1});
  }
  glm::vec3 mean(0.0f);
  for (const glm::vec3& p : s.rest)
    mean += p;
  mean /= float(n);
  for (glm::vec3& p : s.rest)
    p -= mean;
  const auto spring = [&s](int a, int b) {
    s.springs.push_back({a, b, glm::length(s.rest[std::size_t(b)] - s.rest[std::size_t(a)])});
  };
  if (n <= 4) {
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        spring(a, b);
  } else {
    for (int i = 0; i + 1 < n; ++i)
      spring(i, i + 1);
    for (int i = 0; i + 2 < n; ++i)
      spring(i, i + 2);
  }
  return s;
}

}  // namespace

const MoleculeShape& moleculeShape(int complexity) {
  static const std::array<MoleculeShape, 7> shapes = [] {
    std::array<MoleculeShape, 7> all;
    for (int n = 2; n <= 8; ++n)
      all[std::size_t(n - 2)] = makeShape(n);
    return all;
  }();
  if (complexity < MoleculeSettings::kMinComplexity ||
      complexity > MoleculeSettings::kMaxComplexity)
    throw Error(concat("molecule complexity ", complexity, ": expected 2..8 particles"));
  return shapes[std::size_t(complexity - 2)];
}

}  // namespace sandstorm
