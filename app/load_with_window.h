// loadWithWindow: long work before the walls open (`sandstorm FILE`'s field
// in a format whose header does not frame the scene: every one but .vti,
// .pvti, a legacy .vtk of STRUCTURED_POINTS and a .pvd series of them) run
// where a person can watch
// it. (Those, and a configuration's field, are read while the walls open:
// their windows show its progress, RenderContext.)
// Where the run opens windows the
// work goes to a thread of its own while the main thread shows its progress
// (ProgressBoard: what is read, how much, how fast, the time left) in a
// small window (ProgressWindow), beside the log's lines on the terminal;
// the window closes when the work is done. Work done within half a second
// shows no window; without windows the work runs on this thread.
#pragma once

#include <functional>

#include "app/scene_setup.h"

namespace sandstorm {

// Returns what `load` returns and throws what it throws.
FieldSource loadWithWindow(const std::function<FieldSource()>& load, bool windows);

}  // namespace sandstorm
