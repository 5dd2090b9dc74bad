// FrameChannel: hands the main context's frame packets to every render context.
//
// The main context publishes packets in frame order; each consumer (a wall)
// takes every packet in order. publish() waits while the slowest consumer is
// more than `depth` frames behind, so a slow wall slows the main context and
// no wall ever skips a frame. close() wakes everyone: take() hands out what
// was published before, then returns null.
// A consumer that leaves (its wall failed) stops holding the others back.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <vector>

#include "core/sim/frame_packet.h"

namespace sandstorm {

class FrameChannel {
 public:
  FrameChannel(int consumers, int depth = 2);

  // False when the channel was closed while waiting.
  bool publish(std::shared_ptr<const FramePacket> packet);
  // The consumer's next packet, or null once closed.
  std::shared_ptr<const FramePacket> take(int consumer);
  // Waits at most `timeout` for take() to have an answer at once: true when
  // the consumer's next packet is there or the channel closed. A wall opened
  // before its first packet shows what it waits for meanwhile.
  bool waitFor(int consumer, std::chrono::milliseconds timeout);
  void leave(int consumer);
  void close();
  bool closed() const;

 private:
  void trim();

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::shared_ptr<const FramePacket>> packets_;
  std::uint64_t first_ = 0;          // sequence number of packets_.front()
  std::vector<std::uint64_t> next_;  // per consumer: the sequence number it takes next
  std::vector<bool> active_;
  int depth_;
  bool closed_ = false;
};

}  // namespace sandstorm
