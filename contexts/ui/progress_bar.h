// drawProgressBar: long work's share done as a bar, drawn with scissored
// clears only, so it needs no shader: it shows in a window before any program
// is built (the loading window, ProgressWindow) and on a wall whose programs
// are built while it waits for its first frame (RenderContext). Needs a GL
// context current with the framebuffer to draw into bound; leaves the
// scissor test off.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

// Clears `viewport` (x, y, width, height in the framebuffer's pixels) to a
// dark grey and draws within it a framed bar over the pixels `bar` (the same
// form), filled from the left by `share` (0..1).
void drawProgressBar(glm::ivec4 viewport, glm::ivec4 bar, double share);

// A bar across the middle of a viewport: `width` of its width, a fortieth of
// its height tall (at least 6 pixels).
glm::ivec4 centredBar(glm::ivec4 viewport, float width);

}  // namespace sandstorm
