// The ART DTrack ASCII output format (DTrack2/DTrack3 "Technical Appendix"):
// one UDP datagram per measurement, one line per data type, e.g.
//
//   fr 21753
//   ts 39596.024831
//   6dcal 2
//   6d 1 [0 1.000][326.848 -187.216 109.503][-0.9405 -0.3392 -0.0190 ...9 values]
//   6df2 1 1 [0 1.000 6 2][261.1 116.5 41.1][...9 values][1 0.000 -0.500]
//   6df 1 [0 1.000 2][261.1 116.5 41.1 19.65 -57.35 116.60][...9 values]
//   3d 1 [12 1.000][101.2 -34.0 1520.8]
//
// parseDTrack reads fr, ts, 6dcal, 6d, 6df, 6df2 and 3d, and skips any other
// line type (counted in skippedLines). Rotation matrices come column by
// column (b0 b1 b2 is the first column), as glm stores them.
//
// A datagram is taken whole or not at all: any malformed line (a truncated
// block, a count that does not match its blocks, NaN or infinity, an absurd
// id or count, a tracked body whose matrix is not a rotation, bytes that are
// not text, a repeated line type) throws Error naming the line, the item and
// what was expected. Pure: no sockets, no clocks, no allocation beyond the
// datagram's own size.
#pragma once

#include <cstddef>
#include <string_view>

#include "core/tracking/tracker_frame.h"

namespace sandstorm {

struct DTrackLimits {
  static constexpr std::size_t kMaxDatagram = 65536;  // bytes: the largest UDP payload read
  static constexpr int kMaxItems = 256;               // bodies, Flysticks or markers in one line
  static constexpr int kMaxId = 9999;
  static constexpr int kMaxButtons = 256;
  static constexpr int kMaxControllers = 64;
  static constexpr float kMaxCoordinate = 1.0e6f;  // mm: a kilometre
};

TrackerFrame parseDTrack(std::string_view datagram);

}  // namespace sandstorm
