// ART DTrack datagrams, as the tracker's UDP receiver parses them.
#include "core/tracking/dtrack_parser.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sandstorm;
  try {
    parseDTrack(fuzz::asText(data, size));
  } catch (const Error&) {
  }
  return 0;
}
