// ProgressWindow: a small window that shows long work (a field loading)
// before the walls open: a bar filled by the share done, and the log's line
// (share, amounts, rate, time left) as its title. Drawn with scissored
// clears, so it needs no shader and shows even where the walls' programs
// would take long to build. Made, drawn and closed on the main thread (GLFW's rule).
#pragma once

#include <optional>

#include "contexts/platform/glfw_window.h"
#include "core/util/progress_board.h"

namespace sandstorm {

class ProgressWindow {
 public:
  explicit ProgressWindow(const GlfwLibrary& glfw);

  // Draws `work` (none: an empty bar) and shows it.
  void show(const std::optional<ProgressSnapshot>& work);
  bool closed() const { return window_.shouldClose(); }

 private:
  GlfwWindow window_;
};

}  // namespace sandstorm
