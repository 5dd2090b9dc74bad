// writeVti(): a VectorField as VTK XML image data (.vti), written by VTK's own
// vtkXMLImageDataWriter: origin = bounds.min, spacing = the grid spacing (1
// along axes of one point), one Float32 point array `arrayName` (the active
// vectors) and one Float32 point array per scalar array of the field, raw
// binary appended (as ParaView writes), compressed with zlib (the default:
// smallest), LZ4 (several times faster to read) or not at all (read at the
// disk's speed: a series to stream). Throws Error when VTK cannot write the file.
#pragma once

#include <filesystem>
#include <string>

#include "core/field/vector_field.h"

namespace sandstorm {

enum class VtiCompression { ZLib, LZ4, None };

// "zlib", "lz4" or "none"; otherwise Error naming `where` and these.
VtiCompression vtiCompressionNamed(const std::string& name, const std::string& where);

void writeVti(const std::filesystem::path& path, const VectorField& field,
              const std::string& arrayName = "velocity",
              VtiCompression compression = VtiCompression::ZLib);

}  // namespace sandstorm
