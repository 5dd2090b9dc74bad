#include "core/io/vtk_image_frame.h"

namespace sandstorm {

Box VtkImageFrame::bounds() const {
  Box b;
  for (int a = 0; a < 3; ++a) {
    b.min[a] = float(origin[std::size_t(a)] + spacing[std::size_t(a)] * double(extent[2 * a]));
    b.max[a] = float(origin[std::size_t(a)] + spacing[std::size_t(a)] * double(extent[2 * a + 1]));
  }
  return b;
}

glm::ivec3 VtkImageFrame::dims() const {
  return {int(extent[1] - extent[0] + 1), int(extent[3] - extent[2] + 1),
          int(extent[5] - extent[4] + 1)};
}

}  // namespace sandstorm
