// FileIdentity: what cluster ranks compare instead of a step's bytes. A
// file's identity changes with its size and with its modification time, and a
// file that cannot be seen says so.
#include "core/util/file_identity.h"

#include <gtest/gtest.h>

#include <fstream>

namespace sandstorm {
namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "sandstorm-file-identity";
  std::filesystem::create_directories(dir);
  return dir / name;
}

TEST(FileIdentity, ChangesWithTheSizeAndTheModificationTime) {
  const auto path = scratch("step.vti");
  std::ofstream(path) << "twelve bytes";
  const FileIdentity first = FileIdentity::of(path);
  EXPECT_TRUE(first.present);
  EXPECT_EQ(first.size, 12u);
  EXPECT_EQ(FileIdentity::of(path), first);  // the same file, looked at again

  const auto time = std::filesystem::last_write_time(path);
  std::filesystem::last_write_time(path, time + std::chrono::seconds(3));
  const FileIdentity touched = FileIdentity::of(path);
  EXPECT_EQ(touched.size, first.size);
  EXPECT_EQ(touched.modified - first.modified, 3'000'000'000);  // nanoseconds

  std::ofstream(path) << "thirteen byte";
  std::filesystem::last_write_time(path, time + std::chrono::seconds(3));
  const FileIdentity longer = FileIdentity::of(path);
  EXPECT_EQ(longer.modified, touched.modified);
  EXPECT_NE(longer, touched);  // same time, another size
  EXPECT_NE(longer.text().find("13 bytes, modified "), std::string::npos) << longer.text();
}

TEST(FileIdentity, AFileThatCannotBeSeenIsNotPresent) {
  const FileIdentity missing = FileIdentity::of(scratch("no-such-step.vti"));
  EXPECT_FALSE(missing.present);
  EXPECT_EQ(missing, FileIdentity{});
  EXPECT_EQ(missing.text(), "not found");
  EXPECT_FALSE(FileIdentity::of(scratch("")).present);  // a folder is not a step's file
}

}  // namespace
}  // namespace sandstorm
