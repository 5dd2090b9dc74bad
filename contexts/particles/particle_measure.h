// ParticleMeasure: what the main context learns from one wall's particles
// without stalling the frame: how many lie within the probe's radius, and the
// least and greatest value of the colour quantity (for render.color_range =
// "particles"). A compute pass over the live records each frame it is asked
// for; results are read a few frames later from a persistently mapped buffer
// behind fences, never waited for. Needs its GL context current.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/particles/particle_backend.h"

namespace sandstorm {

struct ParticleMeasurement {
  std::uint32_t frame = 0;  // the frame whose particles were measured
  std::uint32_t live = 0;
  std::uint32_t nearProbe = 0;          // within the probe's radius (0 without a probe)
  float least = 0.0f, greatest = 0.0f;  // the colour quantity; equal and 0 with no particle
};

class ParticleMeasure {
 public:
  ParticleMeasure();

  // With the render block bound (the colour quantity): measures frame
  // `frame`'s records. `probe`: the point and its radius, or none.
  void measure(std::uint32_t frame, const ParticleBackend::Records& records, std::size_t capacity,
               std::optional<glm::vec4> probe);
  // The newest measurement the GPU has finished, if any (never waits).
  std::optional<ParticleMeasurement> latest();

 private:
  static constexpr int kSlots = 4;
  gl::Program program_;
  gl::Buffer result_, readBack_;
  const std::uint32_t* mapped_ = nullptr;
  std::array<gl::Sync, kSlots> fences_;
  std::array<std::uint32_t, kSlots> frames_{};
  int next_ = 0;
  std::optional<ParticleMeasurement> latest_;
};

}  // namespace sandstorm
