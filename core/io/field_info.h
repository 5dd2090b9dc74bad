// describeField: what `sandstorm-field info` prints about a loaded field
// file (format, blocks, time steps, arrays, grid, bounds, magnitudes,
// invalid points, notes), one "key: value" line each. The Python module's
// Field.info is the same text.
#pragma once

#include <string>

#include "core/field/vector_field.h"
#include "core/io/load_options.h"

namespace sandstorm {

std::string describeField(const std::string& file, const VectorField& field,
                          const LoadReport& report);

}  // namespace sandstorm
