// readPvd(): the frames of a ParaView data collection (.pvd), the usual way a
// time series of VTK files is stored:
//   <VTKFile type="Collection"><Collection>
//     <DataSet timestep="0.5" part="0" file="step_001.vti"/> ...
// parsed with VTK's own XML parser. File names are relative to the .pvd's
// folder. Frames come back sorted by time; a collection that is empty, names
// no file, repeats a time or has a non-numeric timestep throws Error. Only
// part 0 is read (several parts per time would be pieces of one dataset).
#pragma once

#include <filesystem>
#include <vector>

namespace sandstorm {

struct PvdFrame {
  double time = 0.0;
  std::filesystem::path file;
};

std::vector<PvdFrame> readPvd(const std::filesystem::path& path);

}  // namespace sandstorm
