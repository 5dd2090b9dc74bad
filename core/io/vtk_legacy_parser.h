// parseVtkLegacy: a legacy VTK file (.vtk, "# vtk DataFile Version 2.0" to
// 5.1, ASCII or BINARY) holding STRUCTURED_POINTS, RECTILINEAR_GRID,
// STRUCTURED_GRID, UNSTRUCTURED_GRID or POLYDATA, read by Sandstorm itself:
// VTK's legacy readers trust the file's keywords and counts (a misspelt
// keyword can crash them), so none of them sees the file.
//
// The whole grammar is checked: the header lines, the dataset's geometry
// (DIMENSIONS, ORIGIN, SPACING or ASPECT_RATIO; X/Y/Z_COORDINATES; POINTS;
// CELLS and CELL_TYPES; VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS, as
// counted lists (up to version 4.2) or OFFSETS and CONNECTIVITY (5.x)),
// POINT_DATA and CELL_DATA with SCALARS (+ LOOKUP_TABLE), COLOR_SCALARS,
// LOOKUP_TABLE, VECTORS, NORMALS, TEXTURE_COORDINATES, TENSORS and FIELD
// arrays, each array's METADATA block, and dataset-level FIELD data. Every
// count must agree with DIMENSIONS (or the points and cells), every array
// must fit in the memory budget and in the bytes that are left, ASCII values
// must be numbers and BINARY values (big-endian) must be all there; a cell
// list's sizes must add up to its size and every point id name a point.
// Anything else throws Error "file:line: what was found; what was expected".
// The file's read and its parse each report to a ProgressMeter (bytes): an
// ASCII file parses at some 180 MB/s a core; arrays of 65536 values or more
// are parsed over the cores (ascii_numbers.h). The text is
// given back to the system as the parse passes it, and single-precision
// arrays are kept as float: a BINARY file of floats peaks at about its own
// size (core/util/page_buffer.h).
// Pure C++: no VTK here (the reader checks the cell types: checkVtkCells).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/io/vtk_image_frame.h"

namespace sandstorm {

struct LegacyArray {
  std::string name;
  std::string kind;  // "VECTORS", "SCALARS", "NORMALS", "FIELD", ...
  int components = 1;
  bool singlePrecision = true;  // float data, in `floats`; otherwise double, in `values`
  // Tuples x components. The floats are an array of their own, so that the
  // reader can hand them to VTK without a copy.
  std::unique_ptr<float[]> floats;
  std::size_t floatCount = 0;
  std::vector<double> values;
  std::size_t size() const { return singlePrecision ? floatCount : values.size(); }
};

// Cells as VTK 9 keeps them: cell c's points are connectivity[offsets[c] ..
// offsets[c + 1]).
struct LegacyCells {
  std::vector<std::int64_t> offsets{0};
  std::vector<std::int64_t> connectivity;
  long long count() const { return (long long)offsets.size() - 1; }
};

struct LegacyVtkData {
  enum class Type { StructuredPoints, RectilinearGrid, StructuredGrid, UnstructuredGrid, PolyData };
  Type type = Type::StructuredPoints;
  std::array<long long, 3> dims{1, 1, 1};
  std::array<double, 3> origin{0, 0, 0}, spacing{1, 1, 1};  // structured points
  std::array<std::vector<double>, 3> coordinates;           // rectilinear grid
  std::vector<double> points;  // structured and unstructured grids, polydata: x y z each
  LegacyCells cells;           // unstructured grid
  std::vector<int> cellTypes;  // unstructured grid: VTK cell types
  // Polydata: vertices, lines, polygons, triangle strips.
  std::array<LegacyCells, 4> polyCells;
  std::vector<LegacyArray> pointData, cellData;

  bool pointSet() const { return type == Type::UnstructuredGrid || type == Type::PolyData; }
  long long pointCount() const;
  long long cellCount() const;
};

LegacyVtkData parseVtkLegacy(const std::filesystem::path& path, std::size_t memoryBudget);

// The bytes of a file readVtkLegacyFrame reads: a header and its geometry
// take a few lines (the title at most 256 characters).
inline constexpr std::size_t kLegacyFrameBytes = 65536;

// A STRUCTURED_POINTS file's frame from its header (DIMENSIONS, ORIGIN and
// SPACING or ASPECT_RATIO, before its first POINT_DATA or CELL_DATA), parsed
// as parseVtkLegacy parses it from the file's first kLegacyFrameBytes, no
// array read: `sandstorm FILE` frames its walls with it while the file is
// read. None for other datasets, or where the header gives no frame the
// read would agree with (anything parseVtkLegacy refuses, a geometry that
// does not end within those bytes). Never throws: the read that follows
// says what is wrong with such a file.
std::optional<VtkImageFrame> readVtkLegacyFrame(const std::filesystem::path& path);

}  // namespace sandstorm
