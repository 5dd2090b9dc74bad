// interpolatePointCloud(): point arrays of scattered points (polydata of
// vertices, or points without cells: a particle tracker's or a PIV sheet's
// vectors) at the points of a uniform grid, through VTK's vtkPointInterpolator
// (ParaView's Point Volume Interpolator) with a Shepard kernel: each grid
// point takes the inverse-square-distance weighted mean of the points within
// `radius` of it, and is invalid (its values zero) where there are none.
// For a field whose gradient norm is at most L the error is at most
// L * radius; the caller takes twice the points' mean spacing.
#pragma once

#include <span>
#include <string>

#include "core/io/mesh_resampler.h"

class vtkDataSet;

namespace sandstorm {

// Whether the dataset's cells are all vertices, or it has none.
bool isPointCloud(vtkDataSet* data);

ResampledArrays interpolatePointCloud(std::span<const MeshSource> sources, const UniformGrid& grid,
                                      double radius, const std::string& what);

}  // namespace sandstorm
