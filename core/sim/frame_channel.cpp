#include "core/sim/frame_channel.h"

#include <algorithm>

namespace sandstorm {

FrameChannel::FrameChannel(int consumers, int depth)
    : next_(std::size_t(consumers), 0),
      active_(std::size_t(consumers), true),
      offerTaken_(std::size_t(consumers), false),
      depth_(depth) {}

bool FrameChannel::publish(std::shared_ptr<const FramePacket> packet) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return closed_ || packets_.size() < std::size_t(depth_); });
  if (closed_) return false;
  offered_.reset();  // a hint before packet 0 only: it would hold the grid for good
  packets_.push_back(std::move(packet));
  changed_.notify_all();
  return true;
}

std::shared_ptr<const FramePacket> FrameChannel::take(int consumer) {
  std::unique_lock lock(mutex_);
  const std::size_t c = std::size_t(consumer);
  // Packets published before close() are still delivered, so every wall draws
  // the same frames and the swap barrier never waits for a wall that left early.
  changed_.wait(lock, [&] { return closed_ || next_[c] < first_ + packets_.size(); });
  if (next_[c] >= first_ + packets_.size()) return nullptr;
  std::shared_ptr<const FramePacket> packet = packets_[std::size_t(next_[c] - first_)];
  ++next_[c];
  trim();
  changed_.notify_all();
  return packet;
}

bool FrameChannel::waitFor(int consumer, std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  const std::size_t c = std::size_t(consumer);
  return changed_.wait_for(lock, timeout, [&] {
    return closed_ || next_[c] < first_ + packets_.size() || (offered_ && !offerTaken_[c]);
  });
}

void FrameChannel::offerField(std::shared_ptr<const FieldUpdate> field) {
  std::lock_guard lock(mutex_);
  offered_ = std::move(field);
  std::fill(offerTaken_.begin(), offerTaken_.end(), false);
  changed_.notify_all();
}

std::shared_ptr<const FieldUpdate> FrameChannel::takeOfferedField(int consumer) {
  std::lock_guard lock(mutex_);
  const std::size_t c = std::size_t(consumer);
  if (!offered_ || offerTaken_[c]) return nullptr;
  offerTaken_[c] = true;
  return offered_;
}

void FrameChannel::trim() {
  // Drop packets every active consumer has taken.
  std::uint64_t slowest = first_ + packets_.size();
  for (std::size_t c = 0; c < next_.size(); ++c)
    if (active_[c]) slowest = std::min(slowest, next_[c]);
  while (first_ < slowest && !packets_.empty()) {
    packets_.pop_front();
    ++first_;
  }
}

void FrameChannel::leave(int consumer) {
  std::lock_guard lock(mutex_);
  active_[std::size_t(consumer)] = false;
  trim();
  changed_.notify_all();
}

void FrameChannel::close() {
  std::lock_guard lock(mutex_);
  closed_ = true;
  changed_.notify_all();
}

bool FrameChannel::closed() const {
  std::lock_guard lock(mutex_);
  return closed_;
}

}  // namespace sandstorm
