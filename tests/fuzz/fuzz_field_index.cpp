// A VTK XML file that names other files (.pvtu and the other parallel files,
// .vtm, a .pvd and its parts), with one file it names: the input is the index and that file, split
// at the first line that reads "#---". The index is written as "input" and
// the file as "p0" (no extensions: the loader goes by content), so an index
// that names "p0" reaches the piece and one that names anything else is
// refused before VTK opens it. Its frame as the header gives it
// (readVtkImageFrame) must be the loaded grid's.
#include <optional>

#include "core/io/field_loader.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_xml_check.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  sandstorm::VtkMessageTrap::installOutputWindow();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sandstorm;
  const std::string_view text = fuzz::asText(data, size);
  const std::size_t split = text.find("\n#---\n");
  const std::string_view index = text.substr(0, split);
  const std::string_view piece =
      split == std::string_view::npos ? std::string_view() : text.substr(split + 6);
  fuzz::asFile(reinterpret_cast<const std::uint8_t*>(piece.data()), piece.size(), "p0");
  const auto path =
      fuzz::asFile(reinterpret_cast<const std::uint8_t*>(index.data()), index.size(), "input");
  LoadOptions options;
  options.memoryBudget = fuzz::kBudget;
  std::optional<VectorField> field;
  try {
    field = loadField(path, options);
  } catch (const Error&) {
  }
  // A .pvti's frame from its header (sandstorm FILE frames its walls with it
  // while the pieces are read): never a crash, and where the index loads as
  // the grid the header describes, exactly that grid's bounds.
  const std::optional<VtkImageFrame> frame = readVtkImageFrame(path);
  if (frame && field && field->dims() == frame->dims() &&
      (field->bounds().min != frame->bounds().min || field->bounds().max != frame->bounds().max))
    __builtin_trap();
  return 0;
}
