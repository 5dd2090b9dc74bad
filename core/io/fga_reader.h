// readFga(): an Unreal Engine vector field (.fga, ASCII):
//   nx,ny,nz,
//   minx,miny,minz,
//   maxx,maxy,maxz,
//   vx,vy,vz,    (nx * ny * nz vectors, x fastest)
// Numbers are separated by commas and/or white space. Values sit at voxel
// centres: point i lies at min + (i + 0.5) (max - min) / n. With
// options.convertEngineAxes, Unreal's left-handed centimetres become
// Sandstorm's right-handed metres: 0.01 * (x, -y, z) for positions and
// vectors alike (see load_options.h). Every malformed input (a non-number,
// dims <= 0 or too large, max <= min, too few or too many vectors) throws
// Error naming the file and line. NaN/Inf vectors become zero, counted.
#pragma once

#include <filesystem>

#include "core/field/vector_field.h"
#include "core/io/load_options.h"

namespace sandstorm {

VectorField readFga(const std::filesystem::path& path, const LoadOptions& options,
                    LoadReport& report);

}  // namespace sandstorm
