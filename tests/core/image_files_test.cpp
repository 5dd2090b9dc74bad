// ImageFiles: every queued image is written, as writePng writes it, however
// many are queued at once; a file that cannot be written is reported by
// finish() with its path, and the others are still written.
#include "core/util/image_files.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace sandstorm {
namespace {

Image pattern(int width, int height, int seed) {
  Image image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    image.rgba[i] = std::uint8_t((i * 31 + std::size_t(seed) * 7) % 251);
  return image;
}

std::filesystem::path freshFolder(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(ImageFiles, EveryQueuedImageIsWrittenWhole) {
  const std::filesystem::path dir = freshFolder("sandstorm_image_files");
  ImageFiles files(2);
  for (int i = 0; i < 12; ++i)  // more than its queue holds: write() waits for room
    files.write(pattern(64 + i, 32, i), dir / ("image_" + std::to_string(i) + ".png"));
  EXPECT_TRUE(files.finish().empty());
  for (int i = 0; i < 12; ++i) {
    const Image read = readPng(dir / ("image_" + std::to_string(i) + ".png"));
    const Image expected = pattern(64 + i, 32, i);
    EXPECT_EQ(read.width, expected.width);
    EXPECT_EQ(read.rgba, expected.rgba) << "image " << i;
  }
  std::filesystem::remove_all(dir);
}

TEST(ImageFiles, AFileThatCannotBeWrittenIsReportedByPathAndTheOthersAreWritten) {
  const std::filesystem::path dir = freshFolder("sandstorm_image_files_bad");
  ImageFiles files(1);
  const std::filesystem::path missing = dir / "no such folder" / "front.png";
  files.write(pattern(8, 8, 1), missing);
  files.write(pattern(8, 8, 2), dir / "left.png");
  const std::vector<std::string> failures = files.finish();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_NE(failures[0].find(missing.string()), std::string::npos) << failures[0];
  EXPECT_EQ(readPng(dir / "left.png").rgba, pattern(8, 8, 2).rgba);
  EXPECT_TRUE(files.finish().empty());  // reported once
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sandstorm
