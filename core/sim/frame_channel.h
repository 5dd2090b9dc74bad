// FrameChannel: hands the main context's frame packets to every render context.
//
// The main context publishes packets in frame order; each consumer (a wall)
// takes every packet in order. publish() waits while the slowest consumer is
// more than `depth` frames behind, so a slow wall slows the main context and
// no wall ever skips a frame. close() wakes everyone: take() hands out what
// was published before, then returns null.
// A consumer that leaves (its wall failed) stops holding the others back.
//
// Before packet 0 the main context may offer the field that packet is to
// carry (offerField, AppRun::takeField), so that each wall uploads it while
// the main context still prepares the packet (seeding from the field's mean
// flow, the menu); packet 0 then finds the grid held and uploads nothing.
// A hint only: each consumer takes it at most once, and what the walls draw
// comes from the packets alone.
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
  // Also true when a field is offered that the consumer has not taken.
  bool waitFor(int consumer, std::chrono::milliseconds timeout);
  // Any thread: the field packet 0 will carry (before that packet is published).
  void offerField(std::shared_ptr<const FieldUpdate> field);
  // The offered field if this consumer has not taken it yet, else null.
  std::shared_ptr<const FieldUpdate> takeOfferedField(int consumer);
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
  std::shared_ptr<const FieldUpdate> offered_;
  std::vector<bool> offerTaken_;  // per consumer
  int depth_;
  bool closed_ = false;
};

}  // namespace sandstorm
