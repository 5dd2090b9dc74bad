// SimulationShare: one simulation for the walls whose GL contexts share
// objects (one GPU): the owner wall updates the particles; the others draw
// its buffers. Split first still holds: the owner applies the same packets a
// wall of its own would, so shared and per-wall simulation hold the same
// particles (tests/app/identity_test.cpp), and the update runs once per GPU
// however many walls show it.
//
// Fences keep the GPU work in order across contexts:
//   owner, frame f:  wait (GPU) for every reader's release of frame f-1, whose
//                    buffers update f writes; update; publish f with a fence;
//   reader, frame f: acquire f (CPU waits for the publication, GPU waits for
//                    its fence); draw; release f with a fence.
// Thread-safe: the owner and readers are different wall threads.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <vector>

#include "contexts/gl/objects.h"
#include "contexts/particles/particle_backend.h"

namespace sandstorm {

class SimulationShare {
 public:
  struct Publication {
    ParticleBackend::Records records;
    std::size_t capacity = 0;
    std::size_t lateCount = 0;  // the owner's ParticleBackend::lateCount()
    ShadowHandles shadow;       // the owner's shadow map of the frame
    MoleculeHandles molecules;  // the owner's molecules of the frame (none: no molecules)
  };

  explicit SimulationShare(int readers);

  // Owner thread, its context current.
  void waitForReaders(std::uint32_t frame);
  void publish(std::uint32_t frame, const Publication& what);

  // Reader threads, their contexts current. acquire() throws Error once the
  // share is abandoned (the owner failed).
  Publication acquire(std::uint32_t frame);
  void release(int reader, std::uint32_t frame);

  // Wakes every waiting reader with an error (the owner is gone).
  void abandon();

 private:
  mutable std::mutex mutex_;
  std::condition_variable published_;
  int readers_;
  bool abandoned_ = false;
  std::int64_t latest_ = -1;  // the last frame published
  std::map<std::uint32_t, std::pair<Publication, gl::Sync>> publications_;
  std::map<std::pair<std::uint32_t, int>, gl::Sync> releases_;
};

}  // namespace sandstorm
