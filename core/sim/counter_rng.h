// CounterRng: stateless random numbers keyed by (seed, frame, emitter, index).
//
// Split first needs random numbers that every context, and the CPU reference,
// draw identically without sharing state. A counter-based generator gives that:
// the numbers are a pure function of their key. The mix is pcg4d (Jarzynski &
// Olano, "Hash Functions for GPU Rendering", JCGT 2020), integer-only, so
// shaders/rng.glsl reproduces it bit for bit.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace sandstorm {

// Streams separate the independent draws made for one key.
enum class RngStream : std::uint32_t {
  kBirth = 0,          // box position and lifetime of a new particle
  kBirthBall = 16,     // 16..31: candidates for a position in a sphere or disc
  kVelocityBall = 32,  // 32..47: candidates for the velocity spread
  kMoleculeTurn = 48,  // 48..79: candidates for a newborn molecule's rotation
  kEmission = 255,     // emission count of an emitter (main context)
};

inline glm::uvec4 pcg4d(glm::uvec4 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v ^= v >> 16u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}

// The 64-bit seed travels as two 32-bit halves, as it does to the shaders.
struct Seed {
  std::uint32_t lo = 0;
  std::uint32_t hi = 0;
  static Seed from(std::uint64_t s) { return {std::uint32_t(s), std::uint32_t(s >> 32)}; }
};

inline glm::uvec4 randomBits(Seed seed, std::uint32_t frame, std::uint32_t emitter,
                             std::uint32_t index, RngStream stream) {
  return pcg4d(
      glm::uvec4(index ^ seed.hi, frame, (emitter << 8u) | std::uint32_t(stream), seed.lo));
}

// Four uniform numbers in [0, 1), each with 24 random bits (exact in float).
inline glm::vec4 randomUniform(Seed seed, std::uint32_t frame, std::uint32_t emitter,
                               std::uint32_t index, RngStream stream, std::uint32_t offset = 0) {
  const RngStream s = RngStream(std::uint32_t(stream) + offset);
  return glm::vec4(randomBits(seed, frame, emitter, index, s) >> 8u) * (1.0f / 16777216.0f);
}

}  // namespace sandstorm
