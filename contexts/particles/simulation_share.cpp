#include "contexts/particles/simulation_share.h"

#include <epoxy/gl.h>

#include "core/util/error.h"

namespace sandstorm {
namespace {

GLsync syncOf(const gl::Sync& s) {
  return reinterpret_cast<GLsync>(s.handle());
}

}  // namespace

SimulationShare::SimulationShare(int readers) : readers_(readers) {}

void SimulationShare::waitForReaders(std::uint32_t frame) {
  if (frame == 0) return;
  std::lock_guard lock(mutex_);
  // Every reader released frame - 1 before the swap barrier the owner has passed since.
  for (int r = 0; r < readers_; ++r) {
    const auto it = releases_.find({frame - 1, r});
    if (it != releases_.end()) glWaitSync(syncOf(it->second), 0, GL_TIMEOUT_IGNORED);
  }
  // Older fences and publications are of no further use.
  std::erase_if(releases_, [&](const auto& e) { return e.first.first + 1 < frame; });
  std::erase_if(publications_, [&](const auto& e) { return e.first + 2 < frame; });
}

void SimulationShare::publish(std::uint32_t frame, const Publication& what) {
  gl::Sync fence = gl::createFence();
  glFlush();  // the fence must reach the GPU before other contexts wait on it
  std::lock_guard lock(mutex_);
  publications_[frame] = {what, std::move(fence)};
  latest_ = frame;
  published_.notify_all();
}

SimulationShare::Publication SimulationShare::acquire(std::uint32_t frame) {
  std::unique_lock lock(mutex_);
  published_.wait(lock, [&] { return abandoned_ || latest_ >= std::int64_t(frame); });
  if (abandoned_) throw Error("the wall that runs this GPU's shared simulation stopped");
  const auto it = publications_.find(frame);
  if (it == publications_.end())
    throw Error(concat("shared simulation: frame ", frame, " was never published"));
  glWaitSync(syncOf(it->second.second), 0, GL_TIMEOUT_IGNORED);
  return it->second.first;
}

void SimulationShare::release(int reader, std::uint32_t frame) {
  gl::Sync fence = gl::createFence();
  glFlush();
  std::lock_guard lock(mutex_);
  releases_[{frame, reader}] = std::move(fence);
}

void SimulationShare::abandon() {
  std::lock_guard lock(mutex_);
  abandoned_ = true;
  published_.notify_all();
}

}  // namespace sandstorm
