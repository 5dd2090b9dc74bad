// FieldStreamScanner: the steps of a folder or a .pvd that a simulation is
// writing come out once each, in order, only once their files stopped
// growing; files that arrive out of order, or that a .pvd lists but never
// writes, are skipped with a message; a .pvd caught half written is looked at
// again.
#include "core/io/field_stream_scanner.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/util/error.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << bytes;
}

std::vector<std::string> names(const std::vector<FieldStreamScanner::Step>& steps) {
  std::vector<std::string> out;
  for (const auto& s : steps)
    out.push_back(s.file.filename().string());
  return out;
}

TEST(FieldStreamScanner, AFoldersStepsComeOnceInNameOrderWhenTheyStopGrowing) {
  const fs::path dir = test::scratch() / "stream";
  fs::create_directories(dir);
  FieldStreamScanner scan(dir, 0.5);
  ASSERT_TRUE(scan.folder());
  std::vector<std::string> messages;
  EXPECT_TRUE(scan.poll(messages).empty());
  write(dir / "step_000.vti", "first");
  write(dir / ".hidden.vti", "x");
  write(dir / "notes.txt", "not a field");
  EXPECT_TRUE(scan.poll(messages).empty());  // seen once: maybe still being written
  auto steps = scan.poll(messages);
  ASSERT_EQ(names(steps), std::vector<std::string>{"step_000.vti"});
  EXPECT_EQ(steps[0].time, 0.0);
  // A file that grows between looks is not complete; nor is an empty one.
  write(dir / "step_001.vti", "sec");
  write(dir / "step_002.vti", "");
  scan.poll(messages);
  write(dir / "step_001.vti", "second, longer");
  EXPECT_TRUE(scan.poll(messages).empty());
  steps = scan.poll(messages);
  ASSERT_EQ(names(steps), std::vector<std::string>{"step_001.vti"});  // 002 is empty
  EXPECT_EQ(steps[0].time, 0.5);
  write(dir / "step_002.vti", "third");
  write(dir / "step_003.vti", "fourth");
  scan.poll(messages);
  EXPECT_EQ(names(scan.poll(messages)), (std::vector<std::string>{"step_002.vti", "step_003.vti"}));
  EXPECT_TRUE(scan.poll(messages).empty());  // once each
  EXPECT_TRUE(messages.empty());
  // One named before the newest step arrives late: skipped, said once.
  write(dir / "step_001b.vti", "late");
  scan.poll(messages);
  scan.poll(messages);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("step_001b.vti"), std::string::npos);
  EXPECT_NE(messages[0].find("name order"), std::string::npos);
}

TEST(FieldStreamScanner, APvdsEntriesComeWhenListedAndWrittenInTimeOrder) {
  const fs::path dir = test::scratch() / "stream-pvd";
  fs::create_directories(dir);
  const fs::path pvd = dir / "run.pvd";
  const auto collection = [&](const std::vector<std::pair<double, std::string>>& entries) {
    std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\"><Collection>\n";
    for (const auto& [t, f] : entries)
      text += concat("<DataSet timestep=\"", t, "\" part=\"0\" file=\"", f, "\"/>\n");
    write(pvd, text + "</Collection></VTKFile>\n");
  };
  FieldStreamScanner scan(pvd, 1.0, 3);
  EXPECT_FALSE(scan.folder());
  std::vector<std::string> messages;
  EXPECT_TRUE(scan.poll(messages).empty());  // no .pvd yet
  write(dir / "a.vti", "a");
  collection({{0.0, "a.vti"}});
  scan.poll(messages);
  auto steps = scan.poll(messages);
  ASSERT_EQ(names(steps), std::vector<std::string>{"a.vti"});
  EXPECT_EQ(steps[0].time, 0.0);
  // Half written: does not parse; nothing, and no message.
  write(pvd, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\"><Collect");
  EXPECT_TRUE(scan.poll(messages).empty());
  // b listed but not written yet, c written: they wait in order; b never comes: skipped.
  write(dir / "c.vti", "c");
  collection({{0.0, "a.vti"}, {0.25, "b.vti"}, {0.5, "c.vti"}});
  EXPECT_TRUE(scan.poll(messages).empty());
  EXPECT_TRUE(scan.poll(messages).empty());
  steps = scan.poll(messages);  // the third look: b skipped; c looked at for the first time
  EXPECT_TRUE(steps.empty());
  steps = scan.poll(messages);
  ASSERT_EQ(names(steps), std::vector<std::string>{"c.vti"});
  EXPECT_EQ(steps[0].time, 0.5);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("b.vti"), std::string::npos);
  EXPECT_NE(messages[0].find("skipped"), std::string::npos);
}

// A simulation on many ranks writes each step as an index beside its pieces:
// the indexes are the steps; a folder of plain meshes has every file a step.
TEST(FieldStreamScanner, AFolderOfMeshStepsAndOfIndexesBesideTheirPieces) {
  const fs::path meshes = test::scratch() / "meshes";
  fs::create_directories(meshes);
  write(meshes / "flow_0.vtu", "a");
  write(meshes / "flow_1.vtu", "b");
  write(meshes / "flow_2.e", "c");
  FieldStreamScanner plain(meshes, 1.0);
  std::vector<std::string> messages;
  plain.poll(messages);
  EXPECT_EQ(names(plain.poll(messages)),
            (std::vector<std::string>{"flow_0.vtu", "flow_1.vtu", "flow_2.e"}));

  const fs::path pieces = test::scratch() / "pieces";
  fs::create_directories(pieces);
  for (const char* name : {"step_0.pvtu", "step_0_0.vtu", "step_0_1.vtu", "step_1.pvtu",
                           "step_1_0.vtu", "step_1_1.vtu"})
    write(pieces / name, name);
  FieldStreamScanner indexed(pieces, 1.0);
  indexed.poll(messages);
  EXPECT_EQ(names(indexed.poll(messages)),
            (std::vector<std::string>{"step_0.pvtu", "step_1.pvtu"}));
}

TEST(FieldStreamScanner, RefusesSourcesItCannotWatch) {
  EXPECT_THROW(FieldStreamScanner(test::scratch() / "x.vti"), Error);
  EXPECT_THROW(FieldStreamScanner(test::scratch(), 0.0), Error);
}

}  // namespace
}  // namespace sandstorm
