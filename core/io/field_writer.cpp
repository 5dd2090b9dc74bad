#include "core/io/field_writer.h"

#include "core/io/field_format.h"
#include "core/io/vdb_writer.h"
#include "core/io/vti_writer.h"
#include "core/util/error.h"

namespace sandstorm {

void saveField(const std::filesystem::path& path, const VectorField& field,
               const std::string& arrayName, VtiCompression compression) {
  switch (formatForExtension(path)) {
    case FieldFormat::VtkImageData:
      return writeVti(path, field, arrayName, compression);
    case FieldFormat::OpenVdb:
      return writeVdb(path, field, arrayName);
    default:
      break;
  }
  throw Error(concat(path.string(), ": cannot write '", path.extension().string(),
                     "' files; expected .vti (VTK XML image data) or .vdb (OpenVDB)"));
}

}  // namespace sandstorm
