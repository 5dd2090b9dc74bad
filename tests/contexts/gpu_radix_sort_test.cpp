// GpuRadixSort against std::stable_sort: random keys of several sizes (one,
// a block, a block and one, sizes that are no multiple of the workgroup's),
// keys with many ties (the values, the keys' first positions, show the sort
// is stable), and a count the GPU holds in a buffer.
#include "contexts/sort/gpu_radix_sort.h"

#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class GpuRadixSortTest : public GlTest {};

gl::Buffer upload(const std::vector<std::uint32_t>& data) {
  gl::Buffer b = gl::createBuffer();
  glNamedBufferStorage(b.id(), GLsizeiptr(std::max<std::size_t>(data.size(), 1) * 4),
                       data.empty() ? nullptr : data.data(), GL_DYNAMIC_STORAGE_BIT);
  return b;
}

std::vector<std::uint32_t> download(const gl::Buffer& b, std::size_t n) {
  std::vector<std::uint32_t> out(n);
  glGetNamedBufferSubData(b.id(), 0, GLsizeiptr(n * 4), out.data());
  return out;
}

// The CPU's answer: (key, first position) pairs stably sorted by key.
void expectSortedLikeTheCpu(const std::vector<std::uint32_t>& keys, const gl::Buffer& gpuKeys,
                            const gl::Buffer& gpuValues, std::size_t n) {
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  const std::vector<std::uint32_t> k = download(gpuKeys, n), v = download(gpuValues, n);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_EQ(v[i], order[i]) << "n " << n << ", position " << i;
    ASSERT_EQ(k[i], keys[order[i]]) << "n " << n << ", position " << i;
  }
}

TEST_F(GpuRadixSortTest, EqualsStableSortForRandomKeysOfManySizes) {
  std::mt19937 rng(7);
  GpuRadixSort sort;
  for (const std::size_t n : {1u, 2u, 255u, 1024u, 1025u, 4099u, 100003u, (1u << 18) + 17u}) {
    for (const bool ties : {false, true}) {
      std::vector<std::uint32_t> keys(n), values(n);
      for (std::size_t i = 0; i < n; ++i) {
        keys[i] = ties ? rng() % 7u * 0x24924924u : rng();
        values[i] = std::uint32_t(i);
      }
      const gl::Buffer k = upload(keys), v = upload(values);
      sort.sort(k.id(), v.id(), std::uint32_t(n));
      SCOPED_TRACE(ties ? "with ties" : "distinct");
      expectSortedLikeTheCpu(keys, k, v, n);
    }
  }
}

TEST_F(GpuRadixSortTest, SortsTheCountTheGpuHoldsAndLeavesTheRestAlone) {
  std::mt19937 rng(11);
  const std::size_t capacity = 5000, n = 3333;
  std::vector<std::uint32_t> keys(capacity), values(capacity);
  for (std::size_t i = 0; i < capacity; ++i) {
    keys[i] = rng();
    values[i] = std::uint32_t(i);
  }
  const gl::Buffer k = upload(keys), v = upload(values);
  const gl::Buffer counter = upload({0xdeadbeefu, std::uint32_t(n)});
  GpuRadixSort sort;
  sort.sortCounted(k.id(), v.id(), capacity, counter.id(), 4);
  expectSortedLikeTheCpu(keys, k, v, n);
  const std::vector<std::uint32_t> rest = download(k, capacity);
  for (std::size_t i = n; i < capacity; ++i)
    ASSERT_EQ(rest[i], keys[i]) << "entry " << i << " past the count moved";
}

}  // namespace
}  // namespace sandstorm
