#include "core/movie/movie_layout.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr int kMaxSide = 16384;

// A placed wall with corners: how its points map into the plane (metres).
struct PlaneMap {
  glm::dvec3 lowerLeft, right, up;  // 3D: corner and unit edges
  glm::dvec2 at, right2, up2;       // 2D: the corner and the unit edges' images
  glm::dvec2 map(const glm::dvec3& p) const {
    const glm::dvec3 d = p - lowerLeft;
    return at + glm::dot(d, right) * right2 + glm::dot(d, up) * up2;
  }
};

std::array<glm::dvec3, 4> cornersOf(const WallCorners& w) {  // LL, LR, UR, UL: around the edge
  return {glm::dvec3(w.lowerLeft), glm::dvec3(w.lowerRight), glm::dvec3(w.upperRight()),
          glm::dvec3(w.upperLeft)};
}

PlaneMap mapOf(const WallCorners& w, glm::dvec2 ll2, glm::dvec2 lr2, glm::dvec2 ul2) {
  const glm::dvec3 ll(w.lowerLeft);
  return {ll,
          glm::normalize(glm::dvec3(w.lowerRight) - ll),
          glm::normalize(glm::dvec3(w.upperLeft) - ll),
          ll2,
          glm::normalize(lr2 - ll2),
          glm::normalize(ul2 - ll2)};
}

glm::dvec3 normalOf(const WallCorners& w) {
  return glm::normalize(
      glm::cross(glm::dvec3(w.lowerRight - w.lowerLeft), glm::dvec3(w.upperLeft - w.lowerLeft)));
}

// Whether p lies on the placed wall `w` (its plane, inside its rectangle), within `tol` metres.
bool onWall(const WallCorners& w, const glm::dvec3& p, double tol) {
  const glm::dvec3 ll(w.lowerLeft), across(w.lowerRight - w.lowerLeft),
      upward(w.upperLeft - w.lowerLeft);
  const glm::dvec3 d = p - ll;
  if (std::abs(glm::dot(d, normalOf(w))) > tol) return false;
  const double a = glm::dot(d, glm::normalize(across)), b = glm::dot(d, glm::normalize(upward));
  return a >= -tol && a <= glm::length(across) + tol && b >= -tol && b <= glm::length(upward) + tol;
}

MoviePlacement placementOf(glm::dvec2 ll, glm::dvec2 lr, glm::dvec2 ul) {
  return {ll, lr - ll, ul - ll};
}

struct Box {
  glm::dvec2 lo{std::numeric_limits<double>::max()}, hi{std::numeric_limits<double>::lowest()};
  void add(const MoviePlacement& p) {
    for (const glm::dvec2& c :
         {p.origin, p.origin + p.right, p.origin + p.up, p.origin + p.right + p.up}) {
      lo = glm::min(lo, c);
      hi = glm::max(hi, c);
    }
  }
  bool empty() const { return hi.x < lo.x; }
};

}  // namespace

glm::ivec2 MoviePlacement::pixels() const {
  return {std::max(1, int(std::lround(glm::length(right)))),
          std::max(1, int(std::lround(glm::length(up))))};
}

std::vector<MoviePlacement> unfoldWalls(const std::vector<MovieWallShape>& walls,
                                        std::size_t root) {
  if (walls.empty()) throw Error("--movie: there are no walls to record");
  if (root >= walls.size()) root = 0;
  std::vector<std::size_t> order;  // the walls in the order they were placed
  std::vector<std::optional<MoviePlacement>> placed(walls.size());
  std::vector<std::optional<PlaneMap>> maps(walls.size());
  double size = 0.0;  // the largest wall edge, for the tolerance
  for (const MovieWallShape& w : walls)
    if (w.corners)
      size = std::max({size, double(glm::length(w.corners->lowerRight - w.corners->lowerLeft)),
                       double(glm::length(w.corners->upperLeft - w.corners->lowerLeft))});
  const double tol = 1e-3 + 1e-4 * size;

  auto placeAlone = [&](std::size_t i) {  // a new piece, right of everything placed
    Box box;
    for (const auto& p : placed)
      if (p) box.add(*p);
    const glm::dvec2 at = box.empty() ? glm::dvec2(0.0) : glm::dvec2(box.hi.x, box.lo.y);
    const MovieWallShape& w = walls[i];
    if (w.corners) {
      const double width = glm::length(w.corners->lowerRight - w.corners->lowerLeft);
      const double height = glm::length(w.corners->upperLeft - w.corners->lowerLeft);
      const glm::dvec2 lr = at + glm::dvec2(width, 0.0), ul = at + glm::dvec2(0.0, height);
      placed[i] = placementOf(at, lr, ul);
      maps[i] = mapOf(*w.corners, at, lr, ul);
    } else {
      const double height = box.empty() ? 1.0 : box.hi.y - box.lo.y;
      placed[i] =
          placementOf(at, at + glm::dvec2(height * w.aspect, 0.0), at + glm::dvec2(0.0, height));
    }
    order.push_back(i);
  };

  // A wall joined to placed wall `a`: coplanar, or along one of its edges.
  auto join = [&](std::size_t i, std::size_t a) -> bool {
    const WallCorners& b = *walls[i].corners;
    const WallCorners& wa = *walls[a].corners;
    const PlaneMap& m = *maps[a];
    const std::array<glm::dvec3, 4> c = cornersOf(b);
    if (std::abs(glm::dot(normalOf(b), normalOf(wa))) > 1.0 - 1e-6 &&
        std::abs(glm::dot(c[0] - glm::dvec3(wa.lowerLeft), normalOf(wa))) <= tol) {
      const glm::dvec2 ll = m.map(c[0]), lr = m.map(c[1]), ul = m.map(c[3]);
      placed[i] = placementOf(ll, lr, ul);
      maps[i] = mapOf(b, ll, lr, ul);
      order.push_back(i);
      return true;
    }
    for (int e = 0; e < 4; ++e) {
      const int p = e, q = (e + 1) % 4;
      if (!onWall(wa, c[std::size_t(p)], tol) || !onWall(wa, c[std::size_t(q)], tol)) continue;
      // Turn the wall about this edge into the plane, away from wall a.
      std::array<glm::dvec2, 4> c2;
      c2[std::size_t(p)] = m.map(c[std::size_t(p)]);
      c2[std::size_t(q)] = m.map(c[std::size_t(q)]);
      const glm::dvec2 edge = c2[std::size_t(q)] - c2[std::size_t(p)];
      glm::dvec2 n = glm::normalize(glm::dvec2(-edge.y, edge.x));
      const MoviePlacement& pa = *placed[a];
      const glm::dvec2 centre = pa.origin + 0.5 * (pa.right + pa.up);
      if (glm::dot(n, centre - c2[std::size_t(p)]) > 0.0) n = -n;
      const double depth = glm::length(c[std::size_t((e + 3) % 4)] - c[std::size_t(p)]);
      c2[std::size_t((e + 3) % 4)] = c2[std::size_t(p)] + depth * n;
      c2[std::size_t((e + 2) % 4)] = c2[std::size_t(q)] + depth * n;
      placed[i] = placementOf(c2[0], c2[1], c2[3]);
      maps[i] = mapOf(b, c2[0], c2[1], c2[3]);
      order.push_back(i);
      return true;
    }
    return false;
  };

  placeAlone(root);
  for (;;) {
    bool progress = false;
    for (std::size_t i = 0; i < walls.size(); ++i) {
      if (placed[i] || !walls[i].corners) continue;
      // Joined to the earliest placed wall it meets: the floor to the front, not to a side.
      const std::vector<std::size_t> byPlacement = order;
      for (std::size_t a : byPlacement)
        if (!placed[i] && maps[a] && join(i, a)) progress = true;
    }
    if (progress) continue;
    const auto next = std::ranges::find_if(placed, [](const auto& p) { return !p; });
    if (next == placed.end()) break;
    placeAlone(std::size_t(next - placed.begin()));
  }
  std::vector<MoviePlacement> out;
  for (const auto& p : placed)
    out.push_back(*p);
  return out;
}

MovieLayout layoutMovie(const std::vector<MovieWallShape>& walls, std::optional<glm::ivec2> size,
                        MovieStereo stereo, std::size_t root) {
  const std::vector<MoviePlacement> unfolded = unfoldWalls(walls, root);
  Box box;
  for (const MoviePlacement& p : unfolded)
    box.add(p);
  const glm::dvec2 extent = glm::max(box.hi - box.lo, glm::dvec2(1e-9));
  MovieLayout layout;
  layout.eyes = stereo == MovieStereo::SideBySide ? 2 : 1;
  double scale = 0.0;  // pixels a metre
  glm::dvec2 offset(0.0);
  if (size) {
    const glm::dvec2 half(size->x / layout.eyes, size->y);
    scale = std::min(half.x / extent.x, half.y / extent.y);
    offset = 0.5 * (half - scale * extent);
    layout.frame = *size;
  } else {
    for (std::size_t i = 0; i < walls.size(); ++i)
      scale = std::max({scale, walls[i].eyeImage.x / glm::length(unfolded[i].right),
                        walls[i].eyeImage.y / glm::length(unfolded[i].up)});
    // Within 16384 pixels a side, both eyes' halves together.
    scale = std::min({scale, kMaxSide / layout.eyes / extent.x, kMaxSide / extent.y});
    auto even = [](double pixels) {  // up to even, forgiving rounding
      const int n = std::max(2, int(std::ceil(pixels - 1e-3)));
      return n + n % 2;
    };
    const glm::ivec2 half(even(scale * extent.x), even(scale * extent.y));
    layout.frame = {half.x * layout.eyes, half.y};
  }
  for (const MoviePlacement& p : unfolded) {
    // Metres (y up) to pixels (y down) of the left half.
    auto toPixels = [&](glm::dvec2 m) {
      return glm::dvec2(offset.x + (m.x - box.lo.x) * scale, offset.y + (box.hi.y - m.y) * scale);
    };
    const glm::dvec2 origin = toPixels(p.origin);
    layout.walls.push_back(
        {origin, toPixels(p.origin + p.right) - origin, toPixels(p.origin + p.up) - origin});
  }
  return layout;
}

}  // namespace sandstorm
