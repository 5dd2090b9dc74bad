// saveField(): writes a VectorField in the format its extension names: .vti
// (writeVti, with `compression`) or .vdb (writeVdb, which compresses as
// OpenVDB does). Other extensions throw Error listing these, and so does a
// path whose folder is missing or cannot be written, before any library is
// asked to write.
#pragma once

#include <filesystem>
#include <string>

#include "core/field/vector_field.h"
#include "core/io/vti_writer.h"

namespace sandstorm {

// saveField's checks of the path alone: a format it writes, in a folder that
// can be written. Made before a long read, so a bad output stops it first.
void checkFieldOutput(const std::filesystem::path& path);

void saveField(const std::filesystem::path& path, const VectorField& field,
               const std::string& arrayName = "velocity",
               VtiCompression compression = VtiCompression::ZLib);

}  // namespace sandstorm
