// Turns the configuration's field and scene sections into the objects the
// main context and the walls share: the vector field and the terrain.
#pragma once

#include <filesystem>
#include <memory>

#include "core/config/app_config.h"
#include "core/field/height_map.h"
#include "core/sim/frame_packet.h"

namespace sandstorm {

// Bakes an analytic field or loads a file (relative paths resolve against the
// config file's folder). Throws Error naming the source on failure.
FieldUpdate makeField(const FieldSpec& spec, const std::filesystem::path& configDir);
std::shared_ptr<const HeightMap> makeTerrain(const SceneSpec& spec, const std::filesystem::path& configDir);

}  // namespace sandstorm
