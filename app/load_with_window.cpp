#include "app/load_with_window.h"

#include <chrono>
#include <future>
#include <memory>

#include "contexts/platform/glfw_window.h"
#include "contexts/ui/progress_window.h"
#include "core/util/error.h"
#include "core/util/log.h"
#include "core/util/progress_board.h"

namespace sandstorm {

FieldSource loadWithWindow(const std::function<FieldSource()>& load, bool windows) {
  if (!windows) return load();
  std::future<FieldSource> work = std::async(std::launch::async, load);
  if (work.wait_for(std::chrono::milliseconds(500)) == std::future_status::ready) return work.get();
  try {
    GlfwLibrary glfw;
    ProgressWindow window(glfw);
    log::info("loading: the progress shows in a window too");
    // Between two pieces of work (the file read, then its checks) the last
    // one seen stays up rather than an empty bar.
    std::optional<ProgressSnapshot> shown;
    while (work.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready &&
           !window.closed()) {
      if (std::optional<ProgressSnapshot> now = ProgressBoard::instance().snapshot()) shown = now;
      window.show(shown);
      GlfwLibrary::pollEvents();
    }
  } catch (const Error& e) {  // no window after all: the terminal still says it
    log::warn("loading: no progress window (", e.what(), ")");
  }
  return work.get();
}

}  // namespace sandstorm
