// readPvd(): the frames of a ParaView data collection (.pvd), the usual way a
// time series of VTK files is stored:
//   <VTKFile type="Collection"><Collection>
//     <DataSet timestep="0.5" part="0" file="step_001.vti"/> ...
// parsed with VTK's own XML parser. File names are relative to the .pvd's
// folder. Frames come back sorted by time. A time may have several parts
// (ParaView writes a part a rank of a parallel run, or a block of a
// multiblock: part="0", part="1", ..., each its own file, and a group):
// they are one dataset, the frame's `parts`, in part order. A collection
// that is empty, names no file, repeats a part of a time (or a time without
// parts) or has a non-numeric timestep or part throws Error.
#pragma once

#include <filesystem>
#include <vector>

namespace sandstorm {

struct PvdFrame {
  double time = 0.0;
  std::vector<std::filesystem::path> parts;  // in part order, one dataset: one file, mostly

  const std::filesystem::path& file() const { return parts.front(); }  // the first part's
};

std::vector<PvdFrame> readPvd(const std::filesystem::path& path);

}  // namespace sandstorm
