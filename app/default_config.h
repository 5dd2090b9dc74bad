// defaultConfig: Sandstorm's own configurations (config/downdraft.toml, the
// default run; config/desktop.toml, the scene `sandstorm FILE` opens a field
// in), found wherever sandstorm is started: a scientist opens a field from
// the folder that holds it, not from Sandstorm's checkout.
#pragma once

#include <filesystem>
#include <string_view>

namespace sandstorm {

// config/`name`, searched in the working directory (a checkout's root, as
// scripts/run starts it), beside the folder of the running executable
// (build/sandstorm -> config/), then in the source tree it was built from.
// The working directory's path when none has it (its error names that path).
std::filesystem::path defaultConfig(std::string_view name);

}  // namespace sandstorm
