// meshResolution(): the grid a mesh is resampled onto when the user names none
// (field.resolution, --dims): points spaced as the mesh's cells are, so the
// grid keeps what the mesh resolves.
//
// The spacing is the median size of the cells (the longest side of each
// cell's box, over up to 20000 cells taken evenly from every block), the same
// along every axis; an axis the data is flat along gets one point. The grid
// is made coarser, keeping its proportions, until it holds at most
// kDefaultPoints points, 64 a cell (32^3 at least: a few small cells far
// apart make no fine grid) and fits the memory budget at `bytesPerPoint`. A
// cloud of points without cells is spaced by its points' density instead.
// `note` says what was chosen and why, naming the setting that chooses
// another.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/io/vtk_blocks.h"

namespace sandstorm {

// 256^3: a grid that loads in seconds and fits any GPU; field.resolution asks
// for more.
constexpr std::size_t kDefaultPoints = std::size_t{1} << 24;

struct SamplingBounds {
  glm::dvec3 min{0.0}, max{0.0};
};

// The box around every block's points.
SamplingBounds boundsOf(const std::vector<VtkBlock>& blocks);

// The mean spacing of the blocks' points over the box: (volume / points) to
// the power of one over the axes the data is not flat along.
double cloudSpacing(const std::vector<VtkBlock>& blocks, const SamplingBounds& bounds);

glm::ivec3 meshResolution(const std::vector<VtkBlock>& blocks, const SamplingBounds& bounds,
                          double bytesPerPoint, std::size_t memoryBudget, std::string& note);

}  // namespace sandstorm
