// readUnityVf(): a Unity volume file (.vf) of vectors, as Unity's VFX Graph
// imports it:
//   version 1: "VF_V", uint16 nx, ny, nz, then nx*ny*nz float3 (x fastest);
//   version 2: "VF2X", uint8 minor version, data type (2 = Vector3), usage,
//              uint16 nx, ny, nz, a float4x4 placing the unit box, then float3s.
// Little-endian. Version 1 has no bounds: the values fill options.unityBounds
// (the unit box at the origin by default). Version 2's matrix may scale and
// translate the unit box (rotations are refused). Values sit at voxel centres.
// With options.convertEngineAxes, Unity's y-up left-handed axes become
// Sandstorm's z-up right-handed ones: (x, y, z) -> (x, z, y) for positions and
// vectors. Scalar files (VF_F, or another data type), zero dimensions, and a
// size that differs from the header's promise throw Error naming the file.
#pragma once

#include <filesystem>

#include "core/field/vector_field.h"
#include "core/io/load_options.h"

namespace sandstorm {

VectorField readUnityVf(const std::filesystem::path& path, const LoadOptions& options,
                        LoadReport& report);

}  // namespace sandstorm
