// The cluster's wire format: frame packets, field grids and sparse grids'
// NanoVDB words as they arrive.
#include <cstring>

#include "core/field/sparse_field.h"
#include "core/sim/frame_packet_codec.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sandstorm;
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  try {
    FieldRefs refs;
    decodePacket(bytes, &refs);
  } catch (const Error&) {
  }
  try {
    decodeField(bytes);
  } catch (const Error&) {
  }
  // A sparse grid checked, then read everywhere: past the check no read may stray.
  std::vector<std::uint32_t> words(size / 4);
  if (!words.empty()) std::memcpy(words.data(), data, words.size() * 4);
  try {
    const SparseField f(std::move(words), "fuzz");
    std::uint64_t n = 0;
    f.forEachActive([&](const glm::vec3&, std::uint64_t c) { n += c; });
    const Box b = f.bounds();
    for (int k = 0; k < 8; ++k)
      f.sample(glm::mix(b.min, b.max, glm::vec3(k & 1, (k >> 1) & 1, (k >> 2) & 1) * 0.7f + 0.1f));
    f.overview(4);
  } catch (const Error&) {
  }
  return 0;
}
