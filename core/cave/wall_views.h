// The views a wall draws in one frame: one for mono (from between the eyes)
// and for the one-eye modes, left then right for the stereo modes. Views look
// at the world (the field and particles) through the navigation, so view.eye
// is in world coordinates, where billboards live.
#pragma once

#include <vector>

#include "core/cave/view.h"
#include "core/cave/viewer.h"
#include "core/config/app_config.h"

namespace sandstorm {

std::vector<View> wallViews(const WallSpec& wall, const Viewer& viewer, float aspect,
                            float nearPlane, float farPlane);

// Whether a wall draws both eyes (the one-eye modes draw one view).
bool isStereo(StereoMode mode);

// Where each eye's view lies in a wall's image of `size` pixels, as (x, y,
// width, height) with y up (GL's viewport): left then right, the halves of a
// side-by-side (left eye on the left) or top-bottom (left eye on top) image;
// the whole image for the other modes (quad-buffered stereo has an image an
// eye, anaglyph mixes both in one).
std::vector<glm::ivec4> eyeViewports(StereoMode mode, glm::ivec2 size);

// An overlay laid out for one eye's image and drawn into each (the menu, the
// legend): the size of that image, and where a point of the whole image
// (y down, e.g. the desktop mouse over a stereo window) falls in it, whichever
// eye's half it is over. Both keep the whole image for the modes without halves.
glm::vec2 eyeImageSize(StereoMode mode, glm::vec2 imageSize);
glm::vec2 pointInEyeImage(StereoMode mode, glm::vec2 imageSize, glm::vec2 point);

// The ray (world coordinates) through a point of a wall's image, `at` in
// [0, 1]^2 of the whole image with y down, from the eye of the view drawn
// there (side-by-side: left eye on the left half; top-bottom: on the top).
// `aspect` as wallViews gets it: the whole image's. `direction` is unit.
struct WorldRay {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 1.0f, 0.0f};
};
WorldRay wallClickRay(const WallSpec& wall, const Viewer& viewer, glm::vec2 at, float aspect,
                      float nearPlane, float farPlane);

}  // namespace sandstorm
