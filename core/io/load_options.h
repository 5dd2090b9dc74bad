// LoadOptions: how loadField() turns a file into a dense VectorField.
// LoadReport: what it found there (for `sandstorm-field info` and logs).
//
// Axis conventions. Sandstorm is z-up and right-handed: x east, y north, z up,
// metres, seconds. VTK and OpenVDB files are taken to be in these axes already
// (scientific data is usually z-up). The engine formats are converted unless
// convertEngineAxes is false:
//   - Unity .vf (y-up, left-handed, metres): (x, y, z)_unity -> (x, z, y).
//   - Unreal .fga (z-up, left-handed, centimetres): (x, y, z)_unreal ->
//     0.01 * (x, -y, z), applied to both the bounds and the vectors.
// Engine fields are 3D textures: their values sit at voxel centres, so the
// grid points lie half a voxel inside the stated box.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/field/box.h"

namespace sandstorm {

// Whether an OpenVDB grid is kept sparse (core/field/sparse_field.h) or
// densified over its active voxels' box (field.storage).
enum class SparseChoice {
  Never,   // dense
  Auto,    // sparse when its active voxels fill under half their box, or the
           // dense grid would pass the memory budget, and it can be (below)
  Always,  // sparse, or an error saying why it cannot be
};

struct LoadOptions {
  // The VTK array (point or cell data) or OpenVDB grid to load, or three
  // one-component arrays joined into a vector ("u,v,w"). Empty: the file's
  // only (or active) vector array or Vec3 grid; an error lists the choices
  // otherwise.
  std::string arrayName;
  // Points per axis of the dense grid made. (0, 0, 0): the file's own
  // resolution (its grid dimensions; one point per voxel of a VDB grid's active
  // bounding box; for meshes, points spaced as their cells: sampling_grid.h).
  // Anything else resamples: VTK data as vtkProbeFilter does
  // (mesh_resampler.h), VDB grids through OpenVDB's samplers, engine formats
  // trilinearly.
  glm::ivec3 resolution{0};
  // With `resolution`, the box a mesh (VTK data resampled: not an image read
  // as it is) is resampled over; unset: the mesh's own bounds. A series'
  // steps of a mesh that moves or grows are sampled straight onto the first
  // step's grid (core/io/series_index.h).
  std::optional<Box> samplingBox;
  // Largest dense grid accepted, in bytes (12 per point). Checked before
  // anything large is allocated; above it loading fails saying how to fit.
  std::size_t memoryBudget = std::size_t{2} << 30;
  // The time step to read of a file that holds several (Exodus, EnSight,
  // OpenFOAM, NetCDF, CGNS): an index into LoadReport::times.
  std::size_t timeStep = 0;
  // field.precision = "half": the vectors rounded to 16-bit floats
  // (VectorField::roundToHalf), for a GPU that keeps them so.
  bool halfPrecision = false;
  // field.precision = "auto": given the bytes a field's grids would take on a
  // GPU as floats, the room there is for them (the app asks the GPUs only for
  // large fields); a grid that would pass it is kept as halves
  // (core/io/precision_choice.h). Unset, or no answer: floats unless halfPrecision.
  std::function<std::optional<double>(double floatBytes)> gpuRoom;
  // A .vdb grid kept sparse (loadSparseField): an axis-aligned, not staggered
  // grid at its own resolution, one time step.
  SparseChoice sparse = SparseChoice::Never;
  // Long reads say how far they are in the log (bytes, rate, time left);
  // off for the steps a series reads in the background.
  bool showProgress = true;
  // Unity and Unreal axes and units to Sandstorm's (see above).
  bool convertEngineAxes = true;
  // Unity .vf files carry no bounds: the box they fill, in Unity units before
  // conversion (Unity's VFX graph default is the unit box at the origin).
  Box unityBounds{glm::vec3(-0.5f), glm::vec3(0.5f)};
};

struct LoadReport {
  std::string format;                   // e.g. "VTK XML image data"
  std::vector<std::string> available;   // arrays or grids present, e.g. "velocity (3 components)"
  std::string arrayName;                // the array or grid loaded
  glm::ivec3 sourceDims{0};             // the file's own grid dimensions (VDB: active bbox)
  bool resampled = false;               // values were interpolated onto a new grid
  std::size_t nonFinite = 0;            // NaN or Inf vectors replaced by zero
  std::size_t outside = 0;              // points outside the file's cells (the validity mask)
  std::uint64_t cells = 0, points = 0;  // in the file (every block)
  std::vector<std::string> blocks;      // a multiblock's blocks: "name: kind, cells, points"
  std::vector<double> times;            // the file's time steps, when it holds several
  std::vector<std::string> notes;       // anything else worth telling the user
  // Those notes the reader has logged already, where it made them (a mesh's
  // resampling, blocks left out): a caller that logs the notes skips these.
  std::vector<std::string> notesLogged;

  // The notes not yet in the log, in order.
  std::vector<std::string> notesToLog() const {
    std::vector<std::string> out;
    for (const std::string& note : notes)
      if (std::find(notesLogged.begin(), notesLogged.end(), note) == notesLogged.end())
        out.push_back(note);
    return out;
  }
};

}  // namespace sandstorm
