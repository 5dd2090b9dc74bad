// The TOML configuration loader, with an include: the input is two files, the
// configuration and "part.toml" it may include, split at the first line that
// reads "#---".
#include "core/config/app_config.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sandstorm;
  const std::string_view text = fuzz::asText(data, size);
  const std::size_t split = text.find("\n#---\n");
  const std::string_view main = text.substr(0, split);
  const std::string_view part =
      split == std::string_view::npos ? std::string_view() : text.substr(split + 6);
  fuzz::asFile(reinterpret_cast<const std::uint8_t*>(part.data()), part.size(), "part.toml");
  try {
    parseConfig(std::string(main), fuzz::scratch() / "config.toml", 4);
  } catch (const Error&) {
  }
  return 0;
}
