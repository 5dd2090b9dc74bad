// A parallel image file (.pvti) of one piece: a .vti's grid read through
// VTK's parallel reader, which sandstorm FILE reads before its walls open
// (only a .vti is framed from its header). The same grid, so the same field.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>

#include "core/io/vtk_xml_check.h"

namespace sandstorm::test {

// Writes `pvti` naming `vti` (beside it) as its one piece, with `vti`'s frame.
inline void writePvtiFor(const std::filesystem::path& vti, const std::filesystem::path& pvti) {
  const std::optional<VtkImageFrame> frame = readVtkImageFrame(vti);
  ASSERT_TRUE(frame) << vti;
  std::ostringstream extent;
  for (long long e : frame->extent)
    extent << e << " ";
  std::ofstream out(pvti);
  out << std::setprecision(17)
      << "<VTKFile type=\"PImageData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<PImageData WholeExtent=\"" << extent.str() << "\" GhostLevel=\"0\" Origin=\""
      << frame->origin[0] << " " << frame->origin[1] << " " << frame->origin[2] << "\" Spacing=\""
      << frame->spacing[0] << " " << frame->spacing[1] << " " << frame->spacing[2] << "\">\n"
      << "<PPointData Vectors=\"velocity\"><PDataArray type=\"Float32\" Name=\"velocity\" "
         "NumberOfComponents=\"3\"/></PPointData>\n"
      << "<Piece Extent=\"" << extent.str() << "\" Source=\"" << vti.filename().string()
      << "\"/>\n</PImageData>\n</VTKFile>\n";
}

}  // namespace sandstorm::test
