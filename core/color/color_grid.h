// The grids particles are coloured from when the colour is the field's rather
// than the particle's own (ColorQuantity::Vorticity, ColorQuantity::Array): a
// VectorField on the field's points whose x holds the quantity, so it is
// stored, sent, uploaded and sampled like a field (and like it on the GPU).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "core/color/color_scale.h"
#include "core/field/vector_field.h"

namespace sandstorm {

// The scalar array `name` of `field` in x (y = z = 0), with the field's
// validity; null when the field has no such array.
std::shared_ptr<const VectorField> scalarGrid(const VectorField& field, std::string_view name);

// Which grid colouring by `quantity` needs from `field`: none (nullopt) for the
// particle's own quantities, "" for vorticity, else the array's name: `array`,
// or the field's first scalar array when `array` is empty. nullopt too when
// the field has no such array.
std::optional<std::string> colorGridName(ColorQuantity quantity, const std::string& array,
                                         const VectorField& field);

// The grid colorGridName names: vorticityMagnitude(field) for "", else
// scalarGrid(field, name).
std::shared_ptr<const VectorField> makeColorGrid(const VectorField& field, const std::string& name);

}  // namespace sandstorm
