#include "core/editor/field_composer.h"

#include <memory>
#include <vector>

#include "core/editor/primitive_field.h"
#include "core/util/parallel_for.h"

namespace sandstorm {

VectorField composeField(const VectorField& base, const FieldPlacement& placement,
                         std::span<const FieldPrimitive> primitives, ParallelFor* pool) {
  std::vector<std::unique_ptr<PrimitiveField>> parts;
  for (const FieldPrimitive& p : primitives)
    if (p.active()) parts.push_back(std::make_unique<PrimitiveField>(p));
  VectorField out = base;
  if (parts.empty()) return out;
  const glm::ivec3 dims = base.dims();
  const std::span<glm::vec3> values = out.values();  // once: the threads only write
  const std::size_t layers = std::size_t(dims.y) * std::size_t(dims.z);
  const auto body = [&](std::size_t begin, std::size_t end) {
    for (std::size_t layer = begin; layer < end; ++layer) {
      const int j = int(layer % std::size_t(dims.y)), k = int(layer / std::size_t(dims.y));
      for (int i = 0; i < dims.x; ++i) {
        const glm::vec3 room = placement.toRoom(base.pointPosition(i, j, k));
        glm::vec3 sum(0.0f);
        for (const auto& part : parts)
          sum += part->evaluate(room);
        values[out.index(i, j, k)] += placement.vectorToLocal(sum);
      }
    }
  };
  if (pool)
    pool->run(layers, body);
  else
    body(0, layers);
  return out;
}

}  // namespace sandstorm
