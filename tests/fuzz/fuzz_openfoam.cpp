// An OpenFOAM case: the input is its files, each after a line "//@ NAME"
// naming one of the files below (others are ignored, so the fuzzer writes
// nothing else), loaded as a case folder.
#include <array>
#include <filesystem>
#include <string>

#include "core/io/field_loader.h"
#include "core/io/vtk_message_trap.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

constexpr std::array<const char*, 9> kFiles = {"system/controlDict",
                                               "constant/polyMesh/points",
                                               "constant/polyMesh/faces",
                                               "constant/polyMesh/owner",
                                               "constant/polyMesh/neighbour",
                                               "constant/polyMesh/boundary",
                                               "0/U",
                                               "1/U",
                                               "processor0/constant/polyMesh/points"};

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
  namespace fs = std::filesystem;
  const fs::path root = fuzz::scratch() / "case";
  fuzz::asFiles(fuzz::asText(data, size), root, kFiles);
  LoadOptions options;
  options.memoryBudget = fuzz::kBudget;
  try {
    loadField(root, options);
  } catch (const Error&) {
  }
  return 0;
}
