// The cluster's wire format: frame packets and field grids as they arrive.
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
  return 0;
}
