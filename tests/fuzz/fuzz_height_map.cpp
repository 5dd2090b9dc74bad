// The terrain's 16-bit PGM height maps.
#include "core/field/height_map_io.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sandstorm;
  try {
    readHeightMapPgm(fuzz::asFile(data, size, "terrain.pgm"),
                     Box{{-50.0f, -50.0f, 0.0f}, {50.0f, 50.0f, 8.0f}});
  } catch (const Error&) {
  }
  return 0;
}
