// Files that name .vti files as their parts. A .vti as the one part, so that
// they hold its very grid and load as the same field: a parallel image file
// (.pvti), which `sandstorm FILE` frames from its header as it frames the
// .vti, and a multiblock file (.vtm), which it reads before its walls open.
// And a .pvti of several pieces (writePvti).
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/io/vtk_xml_check.h"

namespace sandstorm::test {

inline std::string extentText(const std::array<long long, 6>& extent) {
  std::ostringstream text;
  for (long long e : extent)
    text << e << " ";
  return text.str();
}

// Writes `pvti` over `frame`, a float vector array "velocity" in each of
// `pieces` (their extents and their .vti files, beside it).
inline void writePvti(
    const std::filesystem::path& pvti, const VtkImageFrame& frame,
    const std::vector<std::pair<std::array<long long, 6>, std::filesystem::path>>& pieces) {
  std::ofstream out(pvti);
  out << std::setprecision(17)
      << "<VTKFile type=\"PImageData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<PImageData WholeExtent=\"" << extentText(frame.extent) << "\" GhostLevel=\"0\" Origin=\""
      << frame.origin[0] << " " << frame.origin[1] << " " << frame.origin[2] << "\" Spacing=\""
      << frame.spacing[0] << " " << frame.spacing[1] << " " << frame.spacing[2] << "\">\n"
      << "<PPointData Vectors=\"velocity\"><PDataArray type=\"Float32\" Name=\"velocity\" "
         "NumberOfComponents=\"3\"/></PPointData>\n";
  for (const auto& [extent, file] : pieces)
    out << "<Piece Extent=\"" << extentText(extent) << "\" Source=\"" << file.filename().string()
        << "\"/>\n";
  out << "</PImageData>\n</VTKFile>\n";
}

// Writes `pvti` naming `vti` (beside it) as its one piece, with `vti`'s frame.
inline void writePvtiFor(const std::filesystem::path& vti, const std::filesystem::path& pvti) {
  const std::optional<VtkImageFrame> frame = readVtkImageFrame(vti);
  ASSERT_TRUE(frame) << vti;
  writePvti(pvti, *frame, {{frame->extent, vti}});
}

// Writes `vtm` naming `vti` (beside it) as its one block.
inline void writeVtmFor(const std::filesystem::path& vti, const std::filesystem::path& vtm) {
  std::ofstream out(vtm);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      << "<vtkMultiBlockDataSet>\n<DataSet index=\"0\" name=\"grid\" file=\""
      << vti.filename().string() << "\"/>\n</vtkMultiBlockDataSet>\n</VTKFile>\n";
}

}  // namespace sandstorm::test
