// --set for configuration settings: `--set gpu.update_items=2` or
// `--set field.source=data/storm.vti` changes a key of [run], [gpu], [field],
// [scene], [head], [navigation], [tracking], [cluster] or [menu] for one run,
// as if a file read after the configuration set it: validated the same way,
// its errors naming the --set. Keys the attribute table knows (sim.*,
// render.*, field.mode, emitter.N.*, ...) stay attributes (applySets, app/).
// Defined with the loader (config_loader.cpp), which reads them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/config/app_config.h"

namespace sandstorm {

// Whether `key` is a configuration setting --set changes (not an attribute).
bool isConfigSetting(std::string_view key);

// Reads the configuration settings among `sets` ("key=value"; the others are
// left alone) on top of `config`, in order. A value is read as TOML (2,
// 0.5, true, [1, 2, 3], "text"), and as text where TOML cannot read it
// (field.source=data/storm.vti). Throws Error naming the --set.
void applyConfigSets(AppConfig& config, const std::vector<std::string>& sets);

}  // namespace sandstorm
