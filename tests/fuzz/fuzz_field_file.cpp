// One fuzz target per field format: the input is a file of that format's
// extension, loaded by loadField (which sniffs the content) with a small
// memory budget. Built once per format with SANDSTORM_FUZZ_EXTENSION.
#include <cstring>

#include "core/io/field_loader.h"
#include "core/io/vtk_message_trap.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  sandstorm::VtkMessageTrap::installOutputWindow();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sandstorm;
  // NetCDF-4 files are HDF5 inside, parsed by libhdf5 before any check of
  // ours can run: not this project's parser to fuzz (tests/fuzz/README.md).
  if (size >= 8 && std::memcmp(data, "\x89HDF\r\n\x1a\n", 8) == 0) return 0;
  const auto path = fuzz::asFile(data, size, std::string("input") + SANDSTORM_FUZZ_EXTENSION);
  LoadOptions options;
  options.memoryBudget = fuzz::kBudget;
  try {
    loadField(path, options);
  } catch (const Error&) {
  }
  return 0;
}
