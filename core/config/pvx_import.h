// ParaView's CAVE files (.pvx): one <Machine> per display, with its screen as
// LowerLeft / LowerRight / UpperRight corners (UpperLeft is derived) and,
// optionally, Geometry="WxH+X+Y" and FullScreen. Machine i is driven by MPI
// rank i in cluster mode, as in ParaView. ParaView CAVEs are usually
// y-up; `yUp` turns them into Sandstorm's z-up room (x, y, z) -> (x, -z, y),
// so a front wall at z = -1.5 lands at y = +1.5, ahead of the user.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/config/app_config.h"

namespace sandstorm {

// Throws Error naming the file and the machine for anything malformed; every
// wall's corners are checked to be a rectangle.
std::vector<WallSpec> readPvx(const std::filesystem::path& path, bool yUp);
std::vector<WallSpec> parsePvx(const std::string& text, const std::string& name, bool yUp);

}  // namespace sandstorm
