// ParaView CAVE files (.pvx), read for a configuration's walls.
#include "core/config/pvx_import.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sandstorm;
  try {
    readPvx(fuzz::asFile(data, size, "cave.pvx"), true);
  } catch (const Error&) {
  }
  return 0;
}
