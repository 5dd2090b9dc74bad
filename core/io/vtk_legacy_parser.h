// parseVtkLegacy: a legacy VTK file (.vtk, "# vtk DataFile Version 2.0" to
// 5.1, ASCII or BINARY) holding STRUCTURED_POINTS, RECTILINEAR_GRID or
// STRUCTURED_GRID, read by Sandstorm itself: VTK's legacy readers trust the
// file's keywords and counts (a misspelt keyword can crash them), so none of
// them sees the file.
//
// The whole grammar is checked: the header lines, the dataset's geometry
// (DIMENSIONS, ORIGIN, SPACING or ASPECT_RATIO; X/Y/Z_COORDINATES; POINTS),
// POINT_DATA and CELL_DATA with SCALARS (+ LOOKUP_TABLE), COLOR_SCALARS,
// LOOKUP_TABLE, VECTORS, NORMALS, TEXTURE_COORDINATES, TENSORS and FIELD
// arrays, each array's METADATA block, and dataset-level FIELD data. Every
// count must agree with DIMENSIONS, every array must fit in the memory
// budget and in the bytes that are left, ASCII values must be numbers and
// BINARY values (big-endian) must be all there. Anything else throws Error
// "file:line: what was found; what was expected". Pure C++: no VTK here.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace sandstorm {

struct LegacyArray {
  std::string name;
  std::string kind;  // "VECTORS", "SCALARS", "NORMALS", "FIELD", ...
  int components = 1;
  bool singlePrecision = true;  // float data (kept as float); otherwise double
  std::vector<double> values;   // tuples x components
};

struct LegacyVtkData {
  enum class Type { StructuredPoints, RectilinearGrid, StructuredGrid };
  Type type = Type::StructuredPoints;
  std::array<long long, 3> dims{1, 1, 1};
  std::array<double, 3> origin{0, 0, 0}, spacing{1, 1, 1};  // structured points
  std::array<std::vector<double>, 3> coordinates;           // rectilinear grid
  std::vector<double> points;                               // structured grid, x y z each
  std::vector<LegacyArray> pointData, cellData;

  long long pointCount() const { return dims[0] * dims[1] * dims[2]; }
  long long cellCount() const;
};

LegacyVtkData parseVtkLegacy(const std::filesystem::path& path, std::size_t memoryBudget);

}  // namespace sandstorm
