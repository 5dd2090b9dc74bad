// The views a wall draws in one frame: one for mono, left then right for the
// stereo modes. Views look at the world (the field and particles) through the
// navigation, so view.eye is in world coordinates, where billboards live.
#pragma once

#include <vector>

#include "core/cave/view.h"
#include "core/cave/viewer.h"
#include "core/config/app_config.h"

namespace sandstorm {

std::vector<View> wallViews(const WallSpec& wall, const Viewer& viewer, float aspect,
                            float nearPlane, float farPlane);

bool isStereo(StereoMode mode);

}  // namespace sandstorm
