// saveField(): writes a VectorField in the format its extension names: .vti
// (writeVti, with `compression`) or .vdb (writeVdb, which compresses as
// OpenVDB does). Other extensions throw Error listing these.
#pragma once

#include <filesystem>
#include <string>

#include "core/field/vector_field.h"
#include "core/io/vti_writer.h"

namespace sandstorm {

void saveField(const std::filesystem::path& path, const VectorField& field,
               const std::string& arrayName = "velocity",
               VtiCompression compression = VtiCompression::ZLib);

}  // namespace sandstorm
