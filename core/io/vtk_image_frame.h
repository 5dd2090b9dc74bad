// VtkImageFrame: where a .vti's image lies, as its header says (the ImageData
// element's WholeExtent, Origin and Spacing), read without reading any array
// (readVtkImageFrame, vtk_xml_check.h): `sandstorm FILE` frames its walls with
// it while the arrays are read. Its bounds and point counts are the ones the
// loaded field gets (copyImage in vtk_field_extractor.cpp does the same
// arithmetic on the values VTK reads from the same attributes).
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "core/field/box.h"

namespace sandstorm {

struct VtkImageFrame {
  std::array<long long, 6> extent{};  // x0 x1 y0 y1 z0 z1, each axis's first and last point
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  std::array<double, 3> spacing{1.0, 1.0, 1.0};

  // float(origin + spacing * extent), axis by axis.
  Box bounds() const;
  glm::ivec3 dims() const;
};

}  // namespace sandstorm
