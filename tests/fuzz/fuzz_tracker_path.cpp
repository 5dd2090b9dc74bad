// sandstorm-tracker-sim's path files.
#include "core/tracking/tracker_script.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sandstorm;
  try {
    const TrackerScript s =
        TrackerScript::parse(std::string(fuzz::asText(data, size)), "path.toml");
    s.at(1.5, 1);
  } catch (const Error&) {
  }
  return 0;
}
