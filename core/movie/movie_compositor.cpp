#include "core/movie/movie_compositor.h"

#include <algorithm>
#include <cmath>

#include "core/util/error.h"

namespace sandstorm {
namespace {

Image crop(const Image& image, int x, int y, int width, int height) {
  Image out{width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 4)};
  for (int row = 0; row < height; ++row)
    std::copy_n(image.rgba.data() + (std::size_t(y + row) * std::size_t(image.width) + x) * 4,
                std::size_t(width) * 4,
                out.rgba.data() + std::size_t(row) * std::size_t(width) * 4);
  return out;
}

// Bilinear at (x, y) in pixel units with pixel centres on integers, clamped to the edge.
void sample(const Image& image, double x, double y, std::uint8_t* out) {
  x = std::clamp(x, 0.0, double(image.width - 1));
  y = std::clamp(y, 0.0, double(image.height - 1));
  const int x0 = int(x), y0 = int(y);
  const int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  const double fx = x - x0, fy = y - y0;
  const auto at = [&](int px, int py, int c) {
    return double(image.rgba[(std::size_t(py) * std::size_t(image.width) + px) * 4 + c]);
  };
  for (int c = 0; c < 3; ++c) {
    const double top = at(x0, y0, c) * (1.0 - fx) + at(x1, y0, c) * fx;
    const double bottom = at(x0, y1, c) * (1.0 - fx) + at(x1, y1, c) * fx;
    out[c] = std::uint8_t(std::lround(top * (1.0 - fy) + bottom * fy));
  }
  out[3] = 255;
}

}  // namespace

std::vector<Image> splitEyes(const Image& image, StereoMode mode) {
  if (mode == StereoMode::SideBySide && image.width >= 2)
    return {crop(image, 0, 0, image.width / 2, image.height),
            crop(image, image.width / 2, 0, image.width / 2, image.height)};
  if (mode == StereoMode::TopBottom && image.height >= 2)
    return {crop(image, 0, 0, image.width, image.height / 2),
            crop(image, 0, image.height / 2, image.width, image.height / 2)};
  return {image};
}

MovieCompositor::MovieCompositor(MovieLayout layout) : layout_(std::move(layout)) {}

void MovieCompositor::compose(const std::vector<std::vector<Image>>& eyes, Image& frame) {
  if (eyes.size() != layout_.walls.size())
    throw Error(concat("MovieCompositor: ", eyes.size(), " walls' images for a layout of ",
                       layout_.walls.size()));
  frame.width = layout_.frame.x;
  frame.height = layout_.frame.y;
  frame.rgba.assign(std::size_t(frame.width) * std::size_t(frame.height) * 4, 0);
  for (std::size_t i = 3; i < frame.rgba.size(); i += 4)
    frame.rgba[i] = 255;
  const double halfWidth = double(layout_.frame.x / layout_.eyes);
  for (std::size_t w = 0; w < eyes.size(); ++w) {
    const MoviePlacement& p = layout_.walls[w];
    const double det = p.right.x * p.up.y - p.right.y * p.up.x;
    if (eyes[w].empty() || std::abs(det) < 1e-12) continue;
    glm::dvec2 lo = glm::min(glm::min(p.origin, p.origin + p.right),
                             glm::min(p.origin + p.up, p.origin + p.right + p.up));
    glm::dvec2 hi = glm::max(glm::max(p.origin, p.origin + p.right),
                             glm::max(p.origin + p.up, p.origin + p.right + p.up));
    for (int eye = 0; eye < layout_.eyes; ++eye) {
      const Image& source = eyes[w][std::min<std::size_t>(std::size_t(eye), eyes[w].size() - 1)];
      if (source.width <= 0 || source.height <= 0) continue;
      const double shift = eye * halfWidth;
      const int x0 = std::max(0, int(std::floor(lo.x + shift)));
      const int x1 = std::min(frame.width, int(std::ceil(hi.x + shift)));
      const int y0 = std::max(0, int(std::floor(lo.y)));
      const int y1 = std::min(frame.height, int(std::ceil(hi.y)));
      if (x1 <= x0 || y1 <= y0) continue;
      rows_.run(std::size_t(y1 - y0), [&](std::size_t begin, std::size_t end) {
        for (std::size_t r = begin; r < end; ++r) {
          const int y = y0 + int(r);
          for (int x = x0; x < x1; ++x) {
            // The pixel's centre in the wall's own coordinates: s right, t up, in [0, 1).
            const glm::dvec2 d = glm::dvec2(x + 0.5 - shift, y + 0.5) - p.origin;
            const double s = (d.x * p.up.y - d.y * p.up.x) / det;
            const double t = (p.right.x * d.y - p.right.y * d.x) / det;
            if (s < 0.0 || s >= 1.0 || t < 0.0 || t >= 1.0) continue;
            sample(source, s * source.width - 0.5, (1.0 - t) * source.height - 0.5,
                   frame.rgba.data() + (std::size_t(y) * std::size_t(frame.width) + x) * 4);
          }
        }
      });
    }
  }
}

}  // namespace sandstorm
