// ParticleSort: the live particles' indices in back-to-front order for one
// view (render.order = sorted): particle_depth_keys.comp makes a key of each
// record's distance from the eye (farther first) and its index as the value,
// and the draw command for the count; GpuRadixSort sorts them; billboards are
// then drawn through the indices (particle_render.vert's SORTED path), so the
// blending composites far to near. Nothing is read back: the count stays on
// the GPU.
//
// Needs its GL context current for every call.
#pragma once

#include <cstddef>
#include <cstdint>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/particles/particle_backend.h"
#include "contexts/sort/gpu_radix_sort.h"

namespace sandstorm {

class ParticleSort {
 public:
  ParticleSort();
  // Sorts the records for the view block bound at binding 1.
  void sort(const ParticleBackend::Records& records, std::size_t capacity);
  // The sorted indices (uint each) and a DrawArraysIndirectCommand drawing them.
  std::uint32_t indices() const { return values_.id(); }
  std::uint32_t command() const { return command_.id(); }

 private:
  void reserve(std::size_t capacity);

  gl::Program keys_;
  GpuRadixSort radix_;
  gl::Buffer keyBuffer_, values_, command_;
  std::size_t capacity_ = 0;
};

}  // namespace sandstorm
