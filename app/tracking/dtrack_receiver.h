// DTrackReceiver: ART DTrack datagrams from a UDP port (unicast, or a
// multicast group), on a thread of its own, keeping the newest complete
// frame. Only the process that owns the main context opens it (rank 0 in
// cluster mode). A datagram is parsed whole (parseDTrack) before it replaces
// the newest frame, so a pose is never half-applied; malformed or oversized
// datagrams are dropped and counted, and the first few say why in the log.
// Only the listed senders (tracking.sender) are heard: anyone else on the
// CAVE's network could otherwise move the head, point the wand and click the
// menu. Their datagrams are dropped unread and counted, the first logged.
#pragma once

#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

#include "app/tracking/tracker_source.h"

namespace sandstorm {

class DTrackReceiver final : public TrackerSource {
 public:
  struct Options {
    int port = 5000;                   // 0: any free port (tests)
    std::string multicast;             // a group to join, e.g. "239.0.0.1"; empty: unicast
    std::vector<std::string> senders;  // IPv4 addresses heard; empty: any (warned)
    std::string interfaceAddress;      // local IPv4 address to listen on; empty: any
  };

  // Binds the port. Throws Error naming the port when it cannot (in use, no permission).
  explicit DTrackReceiver(Options options);
  ~DTrackReceiver() override;
  DTrackReceiver(const DTrackReceiver&) = delete;
  DTrackReceiver& operator=(const DTrackReceiver&) = delete;

  std::optional<TrackerMeasurement> newest() const override;
  TrackerStats stats() const override;
  std::string describe() const override;
  int port() const { return port_; }

 private:
  void run();
  void take(std::string_view datagram, double arrival);
  void drop(const std::string& why);
  void refuse(std::uint32_t sender);

  Options options_;
  std::vector<std::uint32_t> senders_;  // host byte order
  int socket_ = -1;
  int port_ = 0;
  std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  std::optional<TrackerMeasurement> newest_;
  TrackerStats stats_;
  std::thread thread_;
};

}  // namespace sandstorm
