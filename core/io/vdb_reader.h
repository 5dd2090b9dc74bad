// readVdb(): a Vec3 grid of an OpenVDB file as a dense VectorField.
//
// The grid is options.arrayName, or the file's only Vec3 grid (vec3s or
// vec3d); a missing name, a non-Vec3 grid or a choice among several throws
// Error listing the grids and their value types. The file is checked by
// checkVdbFile() before OpenVDB reads it.
//
// The dense grid covers the active voxels' bounding box. With the grid's own
// resolution (options.resolution zero) and an axis-aligned transform, point
// (i, j, k) is voxel bbox.min + (i, j, k) placed by the grid's transform, and
// takes that voxel's value exactly. Otherwise (another resolution, a rotated
// or non-linear transform) the world-space box around the active voxels is
// sampled trilinearly (tools::BoxSampler). Staggered (MAC) grids, whose x
// component lives on the voxel's -x face and so on, are always sampled with
// tools::StaggeredBoxSampler, which averages the faces to the voxel centre.
// Vectors are taken as world-space values (OpenVDB's convention) and are not
// rotated with the transform. Above options.memoryBudget the load is refused
// with a resolution that would fit.
#pragma once

#include <filesystem>

#include <optional>

#include "core/field/sparse_field.h"
#include "core/field/vector_field.h"
#include "core/io/load_options.h"

namespace sandstorm {

VectorField readVdb(const std::filesystem::path& path, const LoadOptions& options,
                    LoadReport& report);

// The grid readVdb() would densify, kept sparse as NanoVDB converts it
// (nanovdb::openToNanoVDB; a vec3d grid rounded to floats first), when
// options.sparse asks for it and the grid can be (axis-aligned, not staggered,
// options.resolution zero); nullopt when options.sparse is Auto and a dense
// grid serves as well. Throws Error when Always cannot be met, or the sparse
// grid would pass options.memoryBudget (checked before it is built).
std::optional<SparseField> readSparseVdb(const std::filesystem::path& path,
                                         const LoadOptions& options, LoadReport& report);

// Calls openvdb::initialize() once (thread-safe). readVdb and writeVdb call it.
void initializeOpenVdb();

}  // namespace sandstorm
