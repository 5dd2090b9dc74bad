#include "app/wall_lines.h"

#include "core/obstacles/collision_shapes.h"

namespace sandstorm {

std::vector<Streamline> wallStreamlines(const ParticleState& state,
                                        const std::shared_ptr<const FieldUpdate>& field,
                                        float fieldBlend, const HeightMap* terrain) {
  PhysicsInputs in;
  in.field = field ? field->field.get() : nullptr;
  in.sparse = field ? field->sparse.get() : nullptr;
  in.nextField = field ? field->next.get() : nullptr;
  in.blend = fieldBlend;
  in.placement = field ? field->placement : FieldPlacement{};
  in.settings = state.sim;
  in.obstacles = collisionShapes(state, terrain);
  return traceStreamlines(state.streamlines, in);
}

std::vector<Streamline> trailLines(const std::vector<Particle>& particles,
                                   const std::vector<std::vector<glm::vec3>>& trails,
                                   std::vector<std::size_t>& owners) {
  std::vector<Streamline> lines;
  owners.clear();
  for (std::size_t i = 0; i < trails.size() && i < particles.size(); ++i) {
    if (trails[i].size() < 2) continue;
    Streamline line;
    for (auto it = trails[i].rbegin(); it != trails[i].rend(); ++it)
      line.points.push_back({*it, particles[i].velocity()});
    line.seedIndex = int(line.points.size()) - 1;  // arc length 0 at the particle
    lines.push_back(std::move(line));
    owners.push_back(i);
  }
  return lines;
}

}  // namespace sandstorm
