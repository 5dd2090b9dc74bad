// MovieCompositor: one movie frame from the walls' pictures, placed by a
// MovieLayout. Each frame pixel inside a wall's placement takes the wall's
// image there, sampled bilinearly at the pixel's centre, so a wall placed at
// its image's own size is copied exactly; everything else is black. Eyes are
// split from the walls' images first (splitEyes).
#pragma once

#include <vector>

#include "core/config/app_config.h"
#include "core/movie/movie_layout.h"
#include "core/util/image.h"
#include "core/util/parallel_for.h"

namespace sandstorm {

// A wall's image as its eyes' images: the halves of a side-by-side (left,
// right) or top-bottom (top is the left eye) image, else the one image.
std::vector<Image> splitEyes(const Image& image, StereoMode mode);

class MovieCompositor {
 public:
  explicit MovieCompositor(MovieLayout layout);

  // `eyes[w]`: wall w's eye images (one: shown to both eyes). `frame` is
  // resized to the layout's frame and overwritten (RGBA, alpha 255).
  void compose(const std::vector<std::vector<Image>>& eyes, Image& frame);
  const MovieLayout& layout() const { return layout_; }

 private:
  MovieLayout layout_;
  ParallelFor rows_;  // the machine's threads (at most 16)
};

}  // namespace sandstorm
