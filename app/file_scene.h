// openFileScene: `sandstorm data.vti` opens a field file as ParaView opens
// one: the field where the walls see it (a desktop camera framing its bounds,
// or, for a configuration with room walls, the field scaled into the room),
// its outline drawn, an emitter seeding a plane across its bounds upstream of
// the mean flow (or its horizontal middle plane when there is none) at a rate
// that fills it, and the particles coloured by speed with a legend. The
// streamline rake (the bounds' diagonal), the slice and the probe (the
// centre) are placed in the field and sized to it, off until turned on.
#pragma once

#include <filesystem>
#include <string>

#include "core/config/app_config.h"
#include "core/field/vector_field.h"
#include "core/io/load_options.h"

namespace sandstorm {

// Rewrites `config` (the desktop scene, or the configuration the user gave)
// around `field`, loaded from `file`. `array`: the file's array or grid, as given.
void openFileScene(AppConfig& config, const std::filesystem::path& file, const std::string& array,
                   const VectorField& field);

// The field openFileScene frames, read from `file`: its grid, or, for an
// OpenVDB grid that field.storage's default keeps sparse, a dense overview of
// it (the run then loads the sparse grid itself).
VectorField fileSceneField(const std::filesystem::path& file, LoadOptions options);

// The emitter the file scene seeds with: exposed for tests.
Emitter seedingPlane(const VectorField& field, int maximum);

}  // namespace sandstorm
