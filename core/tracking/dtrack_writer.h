// Writes a TrackerFrame as a DTrack ASCII datagram (fr, ts, 6dcal, 6d, 6df2
// or 6df, 3d), as an ART DTrack2/DTrack3 controller sends it: the other half
// of parseDTrack, for sandstorm-tracker-sim and the tests. Numbers are written
// with enough digits that parseDTrack reads back the same floats.
#pragma once

#include <string>

#include "core/tracking/tracker_frame.h"

namespace sandstorm {

enum class FlystickFormat { V2, V1 };  // 6df2 (DTrack2 and later), or the older 6df

std::string writeDTrack(const TrackerFrame& frame, FlystickFormat format = FlystickFormat::V2);

}  // namespace sandstorm
