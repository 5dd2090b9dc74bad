// Session logs (--replay): changes, tracking samples and navigation.
#include "core/sim/session_log.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sandstorm;
  try {
    parseSession(std::string(fuzz::asText(data, size)), "fuzz.session");
  } catch (const Error&) {
  }
  return 0;
}
