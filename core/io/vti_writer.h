// writeVti(): a VectorField as VTK XML image data (.vti), written by VTK's own
// vtkXMLImageDataWriter: origin = bounds.min, spacing = the grid spacing (1
// along axes of one point), one Float32 point array `arrayName` (the active
// vectors) and one Float32 point array per scalar array of the field, binary
// appended and zlib-compressed. Throws Error when VTK cannot write the file.
#pragma once

#include <filesystem>
#include <string>

#include "core/field/vector_field.h"

namespace sandstorm {

void writeVti(const std::filesystem::path& path, const VectorField& field,
              const std::string& arrayName = "velocity");

}  // namespace sandstorm
