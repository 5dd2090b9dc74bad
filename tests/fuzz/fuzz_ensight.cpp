// An EnSight Gold case: the input is its files, each after a line
// "//@ NAME" naming one of the files below (others are ignored), loaded
// through flow.case.
#include <array>
#include <filesystem>

#include "core/io/field_loader.h"
#include "core/io/vtk_message_trap.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

constexpr std::array<const char*, 6> kFiles = {"flow.case",      "flow.geo",       "flow.vel",
                                               "flow.00001.geo", "flow.00001.vel", "flow.pre"};

}  // namespace

// VTK's reader leaks on malformed input; a leak's stack unwound in full
// reaches the library the suppressions name (tests/sanitize/lsan-suppressions.txt).
extern "C" const char* __asan_default_options() {
  return "fast_unwind_on_malloc=0";
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  sandstorm::VtkMessageTrap::installOutputWindow();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sandstorm;
  const std::filesystem::path root = fuzz::scratch() / "ensight";
  fuzz::asFiles(fuzz::asText(data, size), root, kFiles);
  LoadOptions options;
  options.memoryBudget = fuzz::kBudget;
  try {
    loadField(root / "flow.case", options);
  } catch (const Error&) {
  }
  return 0;
}
