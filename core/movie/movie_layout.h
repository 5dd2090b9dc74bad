// MovieLayout: where each wall's picture goes in a movie frame. The walls are
// unfolded into the front wall's plane as a CAVE's cross is drawn on paper: a
// wall that shares an edge with a placed one turns about that edge into the
// plane, on the far side from it (the floor below the front, the sides beside
// it, the back beyond a side); a wall in the same plane keeps its place (a
// tiled display wall); a wall touching none, or a perspective-camera wall,
// starts a new piece to the right. Each wall keeps its physical shape, so a
// square CAVE wall is square in the movie whatever its image's pixels.
//
// In a side-by-side movie the frame's left half is this cross for the left
// eye and its right half the same cross for the right eye.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/cave/wall.h"
#include "core/movie/movie_spec.h"

namespace sandstorm {

struct MovieWallShape {
  std::optional<WallCorners> corners;  // none: a camera wall, placed by its image's aspect
  glm::ivec2 eyeImage{0};              // one eye's image as the wall draws it, pixels
  float aspect = 1.0f;                 // a camera wall's view (width / height)
};

// A wall's picture in the frame, in pixels with y down: the wall's lower-left
// corner at `origin`, its lower edge along `right`, its left edge along `up`
// (any rotation or mirror the unfolding gives).
struct MoviePlacement {
  glm::dvec2 origin{0.0}, right{0.0}, up{0.0};
  // The picture's size in pixels (its edges' lengths), for a wall drawn for it.
  glm::ivec2 pixels() const;
};

struct MovieLayout {
  glm::ivec2 frame{0};  // the whole frame, both sides even
  int eyes = 1;         // 2: side by side, the right eye's cross offset by half the frame
  std::vector<MoviePlacement> walls;  // in the left half, in the walls' order
};

// The walls laid out in their unfolded plane, in metres with y up (camera
// walls: one unit high), starting from wall `root` (the front), each joined
// to the earliest placed wall it shares an edge with. Throws Error when
// there are no walls.
std::vector<MoviePlacement> unfoldWalls(const std::vector<MovieWallShape>& walls,
                                        std::size_t root = 0);

// The frame: `size` if given (the cross scaled to fit each half, centred),
// else at the finest pixel density any wall's image has, capped at 16384
// pixels a side.
MovieLayout layoutMovie(const std::vector<MovieWallShape>& walls, std::optional<glm::ivec2> size,
                        MovieStereo stereo, std::size_t root = 0);

}  // namespace sandstorm
