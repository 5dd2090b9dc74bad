#include "core/flow/polyline_color.h"

#include <cmath>

namespace sandstorm {
namespace {

// The array's name in the file: the quantity's, or the field file's array's;
// one the writer already uses gets " (array)" so that neither hides the other.
std::string arrayName(const LineColoring& c) {
  std::string name = c.quantity == ColorQuantity::Array && c.field && !c.field->colorArray.empty()
                         ? c.field->colorArray
                     : c.quantity == ColorQuantity::Age ? std::string("age")
                                                        : std::string(quantityName(c.quantity));
  for (const char* taken :
       {"velocity", "speed", "arc_length", "velocity_x", "velocity_y", "velocity_z"})
    if (name == taken) return name + " (array)";
  return name;
}

}  // namespace

float colorGridAt(const LineColoring& c, const glm::vec3& point) {
  if (!c.field || !c.field->colorGrid) return 0.0f;
  const glm::vec3 local = c.field->placement.toLocal(point);
  float w = c.field->colorGrid->sample(local).x;
  if (c.field->nextColorGrid) w = w + (c.field->nextColorGrid->sample(local).x - w) * c.blend;
  return (c.quantity == ColorQuantity::Vorticity ? std::abs(c.strength) : 1.0f) * w;
}

std::optional<PointArray> streamlineColorArray(std::span<const Streamline> lines,
                                               const LineColoring& c) {
  if (!usesColorGrid(c.quantity) || !c.field || !c.field->colorGrid) return std::nullopt;
  PointArray out{arrayName(c), {}};
  for (const Streamline& l : lines)
    for (const StreamlinePoint& p : l.points)
      out.values.push_back(colorGridAt(c, p.position));
  return out;
}

std::optional<PointArray> trailColorArray(std::span<const Streamline> lines,
                                          std::span<const std::size_t> owners,
                                          std::span<const Particle> particles,
                                          const LineColoring& c) {
  const bool age = c.quantity == ColorQuantity::Age;
  if (!age && !(usesColorGrid(c.quantity) && c.field && c.field->colorGrid)) return std::nullopt;
  PointArray out{arrayName(c), {}};
  for (std::size_t i = 0; i < lines.size() && i < owners.size(); ++i) {
    const Particle& p = particles[owners[i]];
    const float grid = age ? 0.0f : colorGridAt(c, p.position());
    out.values.insert(out.values.end(), lines[i].points.size(), colorValue(p, c.quantity, grid));
  }
  return out;
}

}  // namespace sandstorm
