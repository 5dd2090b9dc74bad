// A legacy .vtk parsed by Sandstorm (parseVtkLegacy) shows its progress as a
// VTK reader's does: its read and its parse are meters on the ProgressBoard
// (what the terminal's lines and the walls' bars show), in bytes, while they
// run, and gone once the file is loaded.
#include <atomic>
#include <chrono>
#include <set>
#include <string>
#include <thread>

#include "core/io/field_loader.h"
#include "core/util/progress_board.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

TEST(VtkLegacyProgress, TheReadAndTheParseAreOnTheProgressBoard) {
  const auto path = test::scratch() / "wind.vtk";
  {
    // 100 x 100 x 60 points of ASCII vectors: 7.8 MB, a few tenths of a second to parse.
    std::string text =
        "# vtk DataFile Version 3.0\nwind\nASCII\nDATASET STRUCTURED_POINTS\n"
        "DIMENSIONS 100 100 60\nORIGIN 0 0 0\nSPACING 1 1 1\nPOINT_DATA 600000\n"
        "VECTORS wind float\n";
    for (int i = 0; i < 600000; ++i)
      text += i % 2 ? "0.5 -0.25 1.125\n" : "1.5 0.75 -2\n";
    test::writeText(path, text);
  }
  std::atomic<bool> loaded{false};
  std::set<std::string> seen;
  bool sane = true;
  std::thread watcher([&] {
    while (!loaded) {
      if (const auto s = ProgressBoard::instance().snapshot()) {
        seen.insert(s->what);
        sane = sane && s->unit == "bytes" && s->done <= s->total &&
               s->total <= std::filesystem::file_size(path);
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  });
  const VectorField field = loadField(path, {});
  loaded = true;
  watcher.join();
  EXPECT_EQ(field.dims(), glm::ivec3(100, 100, 60));
  EXPECT_TRUE(seen.count("parsing wind.vtk")) << "the parse was never on the board";
  EXPECT_TRUE(sane) << "a meter counted other than bytes of the file";
  EXPECT_FALSE(ProgressBoard::instance().snapshot()) << "a meter outlived the load";
}

}  // namespace
}  // namespace sandstorm
