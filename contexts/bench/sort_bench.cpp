#include "contexts/bench/sort_bench.h"

#include <epoxy/gl.h>

#include <random>
#include <vector>

#include "contexts/bench/gpu_stopwatch.h"
#include "contexts/gl/objects.h"
#include "contexts/sort/gpu_radix_sort.h"

namespace sandstorm::bench {

double sortMs(std::size_t keys, int repeats) {
  std::vector<std::uint32_t> data(keys), index(keys);
  std::mt19937 rng(1);
  for (std::size_t i = 0; i < keys; ++i) {
    data[i] = rng();
    index[i] = std::uint32_t(i);
  }
  gl::Buffer source = gl::createBuffer(), k = gl::createBuffer(), v = gl::createBuffer();
  const GLsizeiptr bytes = GLsizeiptr(keys * 4);
  glNamedBufferStorage(source.id(), bytes, data.data(), 0);
  glNamedBufferStorage(k.id(), bytes, nullptr, 0);
  glNamedBufferStorage(v.id(), bytes, index.data(), GL_DYNAMIC_STORAGE_BIT);
  GpuRadixSort sort;
  GpuStopwatch watch;
  for (int r = 0; r <= repeats; ++r) {  // the first sort warms up and is not timed
    glCopyNamedBufferSubData(source.id(), k.id(), 0, 0, bytes);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    if (r > 0) watch.begin();
    sort.sort(k.id(), v.id(), std::uint32_t(keys));
    if (r > 0) watch.end();
  }
  return median(watch.intervalsMs());
}

}  // namespace sandstorm::bench
