// ClusterLink: what App needs from cluster mode, without MPI in sight (the
// MPI implementation is MpiCluster, built only into the sandstorm binary).
//
// Rank 0 runs the main context and send()s each frame's packet; the other
// ranks receive() it. Every rank publishes the packet to its own walls. Wall
// threads report drawn() frames; the main thread then calls swap(), which
// waits for them and for every other rank, and only then lets the walls
// present: one swap barrier across all ranks. Stop requests (a closed window,
// a signal, a failed wall) travel with the barrier, so every rank stops at
// the same frame.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "core/config/app_config.h"
#include "core/sim/frame_packet.h"

namespace sandstorm {

struct AppOptions;
struct FieldSource;

// Cluster mode's command-line options.
struct ClusterOptions {
  bool stats = false;         // --cluster-stats: per-frame bytes and times at the end
  int debugRank = -1;         // the rank that misbehaves on purpose (-1: the last)
  int dieAtFrame = -1;        // --debug-die-at-frame: that rank kills itself (SIGKILL) there
  int hangAtFrame = -1;       // --debug-hang-at-frame: that rank stops (SIGSTOP) there
  int corruptAtFrame = -1;    // --debug-corrupt-at-frame: rank 0 damages that packet in flight
  bool blindToSteps = false;  // --debug-blind-to-steps: that rank cannot see a series' files
  int benchFrames = 0;        // --cluster-bench: this many frames of packets and barriers, no walls
};

class ClusterLink {
 public:
  // Why a rank wants to stop (bits for swap()).
  enum Stop : int { kClosed = 1, kInterrupted = 2, kFailed = 4 };
  struct Verdict {
    bool go = true;       // every rank drew the frame and nobody asked to stop
    bool failed = false;  // a rank failed (exit non-zero)
  };

  virtual ~ClusterLink() = default;

  virtual bool root() const = 0;
  virtual int rank() const = 0;
  // This rank's share: its walls only; per-rank output files; the menu,
  // recording and replay on rank 0 only.
  virtual void localize(AppConfig& config, AppOptions& options) = 0;
  // Whether this rank makes the field itself (rank 0, or every rank with cluster.field = "read").
  virtual bool makesField() const = 0;
  // Every rank reports its set-up (windows, contexts, field): true when all
  // succeeded; otherwise rank 0 has said what failed where, and all stop.
  virtual bool ready(const std::string& error) = 0;
  // cluster.field = "read": every rank's field checked against rank 0's by hash.
  // The last step of start-up: from here on waits are bounded by cluster.timeout_s.
  virtual void shareField(const FieldSource& field) = 0;
  // SIGINT/SIGTERM: waits end soon once this flag is set.
  virtual void watchInterrupt(const std::atomic<bool>* flag) = 0;

  virtual void send(const FramePacket& packet) = 0;          // rank 0
  virtual void sendStop() = 0;                               // rank 0: no packet follows
  virtual std::shared_ptr<const FramePacket> receive() = 0;  // others: null after rank 0 stopped
  virtual void drawn(int wall, std::uint32_t frame) = 0;     // wall threads
  virtual Verdict swap(std::uint32_t frame, int stop, const std::function<bool()>& wallFailed) = 0;
  // After the loop: statistics (--cluster-stats); no further MPI traffic.
  virtual void finish() = 0;
};

}  // namespace sandstorm
