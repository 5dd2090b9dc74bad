#include "core/color/color_grid.h"

#include <vector>

#include "core/field/vorticity.h"

namespace sandstorm {

std::shared_ptr<const VectorField> scalarGrid(const VectorField& field, std::string_view name) {
  const VectorField::Scalars* scalars = field.findScalars(name);
  if (!scalars) return nullptr;
  std::vector<glm::vec3> values(scalars->values.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i].x = scalars->values[i];
  auto grid = std::make_shared<VectorField>(field.bounds(), field.dims(), std::move(values));
  grid->setValidity(std::vector<std::uint8_t>(field.validity().begin(), field.validity().end()));
  return grid;
}

std::optional<std::string> colorGridName(ColorQuantity quantity, const std::string& array,
                                         const VectorField& field) {
  if (quantity == ColorQuantity::Vorticity) return std::string();
  if (quantity != ColorQuantity::Array) return std::nullopt;
  if (array.empty())
    return field.scalars().empty() ? std::nullopt
                                   : std::optional<std::string>(field.scalars().front().name);
  return field.findScalars(array) ? std::optional<std::string>(array) : std::nullopt;
}

std::shared_ptr<const VectorField> makeColorGrid(const VectorField& field,
                                                 const std::string& name) {
  if (name.empty()) return std::make_shared<const VectorField>(vorticityMagnitude(field));
  return scalarGrid(field, name);
}

}  // namespace sandstorm
