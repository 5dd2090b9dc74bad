#include "core/io/field_writer.h"

#include "core/io/field_format.h"
#include "core/io/vdb_writer.h"
#include "core/io/vti_writer.h"
#include "core/util/error.h"
#include "core/util/output_file.h"

namespace sandstorm {

void checkFieldOutput(const std::filesystem::path& path) {
  const FieldFormat format = formatForExtension(path);
  const std::string expected = ".vti (VTK XML image data) or .vdb (OpenVDB)";
  if (path.extension().empty())
    throw Error(concat(path.string(), ": expected a file name ending in ", expected));
  if (format != FieldFormat::VtkImageData && format != FieldFormat::OpenVdb)
    throw Error(concat(path.string(), ": cannot write '", path.extension().string(),
                       "' files; expected ", expected));
  checkOutputFile(path, "writing");
}

void saveField(const std::filesystem::path& path, const VectorField& field,
               const std::string& arrayName, VtiCompression compression) {
  checkFieldOutput(path);
  if (formatForExtension(path) == FieldFormat::VtkImageData)
    writeVti(path, field, arrayName, compression);
  else
    writeVdb(path, field, arrayName);
}

}  // namespace sandstorm
