// One fuzz target per field format: the input is a file of that format's
// extension, loaded by loadField (which sniffs the content) with a small
// memory budget. Built once per format with SANDSTORM_FUZZ_EXTENSION.
#include <cstring>
#include <optional>
#include <string_view>

#include "core/io/field_loader.h"
#include "core/io/vdb_reader.h"
#include "core/io/vtk_legacy_parser.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_xml_check.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

// VTK's Exodus reader leaks on malformed input; a leak's stack unwound in full
// reaches the library the suppressions name (tests/sanitize/lsan-suppressions.txt).
// The other formats keep the fast unwinder.
extern "C" const char* __asan_default_options() {
  return std::string_view(SANDSTORM_FUZZ_EXTENSION) == ".e" ? "fast_unwind_on_malloc=0" : "";
}

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
  std::optional<VectorField> field;
  try {
    field = loadField(path, options);
  } catch (const Error&) {
  }
  // A .vti's or legacy .vtk's frame from its header (sandstorm FILE frames
  // its walls with it while the file is read): never a crash, and where the
  // file loads as the grid the header describes, exactly that grid's bounds.
  const std::string_view extension(SANDSTORM_FUZZ_EXTENSION);
  if (extension == ".vti" || extension == ".vtk") {
    const std::optional<VtkImageFrame> frame =
        extension == ".vti" ? readVtkImageFrame(path) : readVtkLegacyFrame(path);
    if (frame && field && field->dims() == frame->dims() &&
        (field->bounds().min != frame->bounds().min || field->bounds().max != frame->bounds().max))
      __builtin_trap();
  }
  // An OpenVDB grid kept sparse: NanoVDB's conversion and SparseField's check.
  if (std::string_view(SANDSTORM_FUZZ_EXTENSION) == ".vdb") {
    options.sparse = SparseChoice::Always;
    LoadReport report;
    try {
      readSparseVdb(path, options, report);
    } catch (const Error&) {
    }
  }
  return 0;
}
