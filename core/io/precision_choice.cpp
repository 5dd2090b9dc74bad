#include "core/io/precision_choice.h"

#include "core/config/byte_size.h"
#include "core/util/error.h"

namespace sandstorm {

double floatGpuBytes(const VectorField& field, int grids) {
  return double(field.pointCount()) * 16.0 * double(grids);
}

bool chooseHalf(VectorField& field, int grids, const LoadOptions& options, LoadReport& report) {
  if (options.halfPrecision || !options.gpuRoom || field.halfPrecision()) return false;
  const double bytes = floatGpuBytes(field, grids);
  const std::optional<double> room = options.gpuRoom(bytes);
  if (!room || bytes <= *room) return false;
  const std::string held =
      grids == 1 ? "its grid" : concat("the ", grids, " grids it holds at once");
  try {
    field.roundToHalf();
  } catch (const Error& e) {
    report.notes.push_back(concat("field.precision = \"auto\": as floats ", held, " would take ",
                                  formatByteSize(bytes), " of the GPU's ", formatByteSize(*room),
                                  " for fields, but halves cannot hold it (", e.what(),
                                  "); kept as floats: lower field.resolution if the upload fails"));
    return false;
  }
  report.notes.push_back(
      concat("field.precision = \"auto\": 16-bit floats chosen: as floats ", held, " would take ",
             formatByteSize(bytes), " of the GPU's ", formatByteSize(*room),
             " for fields; as halves ", formatByteSize(bytes / 2.0),
             " (each component within 2^-11 of itself; field.precision = \"float\" keeps floats)"));
  return true;
}

}  // namespace sandstorm
