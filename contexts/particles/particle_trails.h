// ParticleTrails: each particle's last K positions (render.trail_length), in
// a ring per record on the GPU, for both backends. The update writes every
// survivor's input record (the compute update's trailSource, or the
// transform-feedback update's captured outSource: source());
// after it, trail_update.comp moves each ring to its particle's new record and
// writes the new position at the head, so a trail follows its particle
// through the compaction. Two sets of rings take turns like the particle
// buffers; changing K or the capacity starts every trail afresh.
//
// Needs its GL context current for every call.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"

namespace sandstorm {

class ParticleTrails {
 public:
  static constexpr int kMaxLength = 64;

  ParticleTrails();

  // Before an update: rings for `capacity` records of `length` positions
  // (made anew, and started afresh, when either changed). Binds the source
  // buffer the update writes.
  void prepare(std::size_t capacity, int length);
  // After the update wrote `positions` (newborn first, `born` of them); its
  // live count is the uint at index `countIndex` of `countBuffer` plus `countAdd`.
  void advance(std::uint32_t positions, std::uint32_t born, std::uint32_t countBuffer,
               int countIndex, std::uint32_t countAdd = 0);
  // The buffer of every output record's input record (uint each), which the update writes.
  std::uint32_t source() const { return source_.id(); }

  std::uint32_t ring() const { return rings_[std::size_t(current_)].id(); }
  int length() const { return length_; }
  int head() const { return head_; }
  // Record i's trail, newest first, the slots holding a position (tests).
  std::vector<std::vector<glm::vec3>> readBack(std::size_t count) const;
  // The same from any context that shares the ring buffer (waits for the GPU).
  static std::vector<std::vector<glm::vec3>> read(std::uint32_t ring, int length, int head,
                                                  std::size_t count);

 private:
  gl::Program program_;
  gl::Program dispatch_;     // the update's dispatch from the live count
  gl::Buffer dispatchArgs_;  // its output
  gl::Buffer source_;
  gl::Buffer rings_[2];
  int current_ = 0;
  std::size_t capacity_ = 0;
  int length_ = 0;
  int head_ = 0;
  bool fresh_ = true;
};

}  // namespace sandstorm
