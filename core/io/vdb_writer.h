// writeVdb(): a VectorField as an OpenVDB file written by openvdb::io::File:
// one Vec3SGrid `gridName` whose transform maps voxel (i, j, k) to grid point
// (i, j, k) (a ScaleTranslateMap: translation bounds.min, scale the spacing,
// 1 along axes of one point). Every grid point is an active voxel, zero
// vectors included, so the active bounding box is the whole grid. Each scalar
// array of the field becomes a FloatGrid of its name on the same transform.
// Throws Error when the file cannot be written.
#pragma once

#include <filesystem>
#include <string>

#include "core/field/vector_field.h"

namespace sandstorm {

void writeVdb(const std::filesystem::path& path, const VectorField& field,
              const std::string& gridName = "velocity");

}  // namespace sandstorm
