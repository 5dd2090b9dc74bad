// saveField(): writes a VectorField in the format its extension names: .vti
// (writeVti) or .vdb (writeVdb). Other extensions throw Error listing these.
#pragma once

#include <filesystem>
#include <string>

#include "core/field/vector_field.h"

namespace sandstorm {

void saveField(const std::filesystem::path& path, const VectorField& field,
               const std::string& arrayName = "velocity");

}  // namespace sandstorm
