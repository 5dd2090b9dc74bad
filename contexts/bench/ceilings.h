// The hardware's own limits, measured in the benchmark's run so each stage can
// be stated as a fraction of them:
//   - copyBandwidth: glCopyNamedBufferSubData between two buffers, counting the
//     bytes read plus the bytes written;
//   - BareTransformFeedback: a pass-through vertex stage captured by transform
//     feedback, records laid out as the particle buffers (two vec4 streams in,
//     two out), no geometry stage;
//   - shaderCopyBandwidth, BareComputeUpdate: the same from compute shaders;
//   - BarePointDraw: the same records drawn as one-pixel points with a trivial
//     vertex and fragment stage into an RGBA16F target.
// All need a current GL context.
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"

namespace sandstorm::bench {

// Bytes per second (read + written), the median of `repeats` copies of `bytes`.
double copyBandwidth(std::size_t bytes, int repeats);
// The same through a compute shader (vec4 loads and stores, 1 to 16 records an
// invocation: the fastest), which a driver cannot hand to a copy engine: the
// bandwidth shaders themselves see.
double shaderCopyBandwidth(std::size_t bytes, int repeats);

// The compute update's own kernel (particle_update.comp) with the physics left
// out (BARE_UPDATE: every record survives unchanged): its data movement and
// scan over `records` records, the ceiling of the compute backend's structure.
class BareComputeUpdate {
 public:
  // `items`: records an invocation, as the compute backend is tuned (GpuTuning).
  BareComputeUpdate(std::size_t records, int items);
  double passMs(int repeats);

 private:
  std::size_t records_;
  int items_;
  gl::Buffer in_[2], out_[2], control_, tiles_, simBlock_;
  gl::Program program_;
};

class BareTransformFeedback {
 public:
  explicit BareTransformFeedback(std::size_t records);
  // Median GPU milliseconds of one pass over every record.
  double passMs(int repeats);

 private:
  std::size_t records_;
  gl::Buffer in_[2], out_[2];
  gl::VertexArray vao_;
  gl::TransformFeedback feedback_;
  gl::Framebuffer target_;
  gl::Renderbuffer color_;
  gl::Program program_;
};

class BarePointDraw {
 public:
  BarePointDraw(std::size_t points, glm::ivec2 size);
  // Median GPU milliseconds of drawing every point once.
  double drawMs(int repeats);

 private:
  std::size_t points_;
  glm::ivec2 size_;
  gl::Buffer records_[2];
  gl::VertexArray vao_;
  gl::Texture color_;
  gl::Framebuffer target_;
  gl::Program fill_, draw_;
};

}  // namespace sandstorm::bench
