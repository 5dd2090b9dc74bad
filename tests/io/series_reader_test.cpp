// A series streamed from disk (indexSeries + SeriesReader): indexed without
// reading its steps, each step read equal to what was written, never more
// than the capacity in memory, and a step that cannot be read named.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <thread>

#include "core/io/series_index.h"
#include "core/io/series_reader.h"
#include "core/io/vti_writer.h"
#include "core/util/error.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

// Step n's value at point i: a formula the test checks against.
glm::vec3 expected(int n, std::size_t i) {
  return glm::vec3(float(n), float(i), -0.25f * float(n * 7 + int(i)));
}

VectorField stepField(int n, glm::ivec3 dims = {4, 3, 2}) {
  VectorField f(Box{{0, 0, 0}, {3, 2, 1}}, dims);
  for (std::size_t i = 0; i < f.pointCount(); ++i)
    f.values()[i] = expected(n, i);
  return f;
}

std::string stepName(int n) {
  char name[32];
  std::snprintf(name, sizeof(name), "step_%04d.vti", n);
  return name;
}

// A .pvd of `steps` entries 0.1 s apart; only the first `written` files exist.
std::filesystem::path writeSeries(const std::filesystem::path& dir, int steps, int written) {
  std::string pvd =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (int n = 0; n < steps; ++n) {
    if (n < written) writeVti(dir / stepName(n), stepField(n));
    pvd += "  <DataSet timestep=\"" + std::to_string(0.1 * n) + "\" part=\"0\" file=\"" +
           stepName(n) + "\"/>\n";
  }
  pvd += "</Collection>\n</VTKFile>\n";
  test::writeText(dir / "series.pvd", pvd);
  return dir / "series.pvd";
}

std::shared_ptr<SeriesReader> readerFor(SeriesIndex& index, std::size_t capacity, int threads) {
  return std::make_shared<SeriesReader>(std::move(index.sources), index.stepOptions, index.first,
                                        capacity, threads);
}

void expectStep(const VectorField& f, int n) {
  for (std::size_t i = 0; i < f.pointCount(); ++i)
    ASSERT_EQ(f.values()[i], expected(n, i)) << "step " << n << ", point " << i;
}

TEST(SeriesReader, AThousandStepSeriesIsIndexedReadingOnlyItsFirstStep) {
  // Only step 0 exists on disk: indexing must not open any other.
  const auto dir = test::scratch();
  LoadReport report;
  SeriesIndex index = indexSeries(writeSeries(dir, 1000, 1), {}, &report);
  ASSERT_EQ(index.times.size(), 1000u);
  ASSERT_EQ(report.times.size(), 1000u);
  EXPECT_NEAR(index.times[999], 99.9, 1e-9);
  EXPECT_EQ(index.sources[999].file.filename(), stepName(999));
  expectStep(*index.first, 0);
  // Step 999 is asked for: it fails, naming its file; the reader goes on.
  auto reader = readerFor(index, 3, 2);
  test::expectError([&] { reader->wait(999); }, {stepName(999)});
  EXPECT_NE(reader->failure(999).find(stepName(999)), std::string::npos);
  EXPECT_EQ(reader->wait(0), index.first);
  EXPECT_EQ(std::filesystem::path(reader->name(1)).filename(), stepName(1));
}

TEST(SeriesReader, ReadsTheWantedStepsAndHoldsNoMoreThanItsCapacity) {
  const auto dir = test::scratch();
  SeriesIndex index = indexSeries(writeSeries(dir, 12, 12), {});
  auto reader = readerFor(index, 4, 2);
  FieldTimeline timeline({0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1}, reader);
  // Play forwards through the series as the main context does, step by step.
  for (std::size_t first = 0; first + 1 < 12; ++first) {
    timeline.readAhead({first, first + 1, 0.5f}, false, false);
    expectStep(*timeline.wait(first), int(first));
    expectStep(*timeline.wait(first + 1), int(first + 1));
    const std::vector<std::size_t> held = reader->resident();
    EXPECT_LE(held.size(), 4u);
    for (std::size_t i : held)  // nothing behind the pair, nothing beyond four steps on
      EXPECT_TRUE(i >= first && i < first + 4) << "step " << i << " held at " << first;
  }
  // Read ahead: the two after the pair come without being waited for.
  timeline.readAhead({2, 3, 0.0f}, false, false);
  for (int tries = 0; tries < 500 && reader->resident().size() < 4; ++tries)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(reader->resident(), (std::vector<std::size_t>{2, 3, 4, 5}));
  EXPECT_EQ(reader->stats().stepsRead, 11u + 4u);  // every step once, then 2..5 again
}

// A watched folder's series grows: a new step is held while wanted, no more
// than the capacity stay, and a step let go is read again from its file.
TEST(SeriesReader, AppendedStepsAreHeldWhileWantedAndReadAgainFromTheirFiles) {
  const auto dir = test::scratch();
  SeriesIndex index = indexSeries(writeSeries(dir, 1, 1), {});
  auto reader = readerFor(index, 3, 1);
  FieldTimeline timeline({0.0}, reader);
  for (int n = 1; n < 8; ++n) {
    writeVti(dir / stepName(n), stepField(n));
    auto step = std::make_shared<const VectorField>(stepField(n));
    timeline.append(0.1 * n, step, dir / stepName(n));
    EXPECT_EQ(timeline.frame(std::size_t(n)), step);  // the very grid, not read again
    EXPECT_LE(reader->resident().size(), 3u) << "after step " << n;
    EXPECT_EQ(reader->identity(std::size_t(n)), FileIdentity::of(dir / stepName(n)));
  }
  EXPECT_EQ(timeline.size(), 8u);
  EXPECT_EQ(reader->stats().stepsRead, 0u);
  // Step 2 was let go: wanted again, it is read from its file.
  timeline.readAhead({2, 3, 0.0f}, false, false);
  expectStep(*timeline.wait(2), 2);
  EXPECT_GE(reader->stats().stepsRead, 1u);
  // A step on another grid joins on the first's (resampled onto it).
  writeVti(dir / "other.vti", stepField(8, {5, 3, 2}));
  timeline.append(0.8, std::make_shared<const VectorField>(stepField(8, {5, 3, 2})),
                  dir / "other.vti");
  EXPECT_EQ(timeline.size(), 9u);
  ASSERT_EQ(reader->size(), 9u);
  EXPECT_EQ(reader->wait(8)->dims(), glm::ivec3(4, 3, 2));
}

// A cluster rank following rank 0's watched folder: steps appended by file
// alone are read when wanted, on the first step's grid.
TEST(SeriesReader, StepsAppendedByFileAreReadWhenWanted) {
  const auto dir = test::scratch();
  SeriesIndex index = indexSeries(writeSeries(dir, 1, 1), {});
  auto reader = readerFor(index, 3, 1);
  for (int n = 1; n < 5; ++n) {
    writeVti(dir / stepName(n), stepField(n));
    reader->appendFile(dir / stepName(n));
    EXPECT_EQ(reader->size(), std::size_t(n + 1));
    EXPECT_EQ(reader->identity(std::size_t(n)), FileIdentity::of(dir / stepName(n)));
    EXPECT_EQ(reader->get(std::size_t(n)), nullptr);  // not read until wanted
  }
  EXPECT_EQ(reader->stats().stepsRead, 0u);
  for (int n : {3, 1, 4})
    expectStep(*reader->wait(std::size_t(n)), n);
  EXPECT_EQ(reader->stats().stepsRead, 3u);
  // A step on another grid is read onto the first's; one that does not read fails, naming it.
  writeVti(dir / "other.vti", stepField(5, {5, 3, 2}));
  reader->appendFile(dir / "other.vti");
  EXPECT_EQ(reader->wait(5)->dims(), glm::ivec3(4, 3, 2));
  test::writeText(dir / "broken.vti", "<VTKFile");
  reader->appendFile(dir / "broken.vti");
  test::expectError([&] { reader->wait(6); }, {"broken.vti"});
}

TEST(SeriesReader, ReadsBackwardsAndAroundALoop) {
  const auto dir = test::scratch();
  SeriesIndex index = indexSeries(writeSeries(dir, 6, 6), {});
  auto reader = readerFor(index, 4, 1);
  const FieldTimeline timeline({0.0, 0.1, 0.2, 0.3, 0.4, 0.5}, reader);
  timeline.readAhead({4, 5, 0.0f}, false, true);  // looping: 0 and 1 come after 5
  for (std::size_t i : {4, 5, 0, 1})
    expectStep(*timeline.wait(i), int(i));
  EXPECT_EQ(reader->resident(), (std::vector<std::size_t>{0, 1, 4, 5}));
  timeline.readAhead({2, 3, 0.0f}, true, false);  // backwards: 1 and 0 before 2
  for (std::size_t i : {0, 1, 2, 3})
    expectStep(*timeline.wait(i), int(i));
  EXPECT_EQ(reader->resident(), (std::vector<std::size_t>{0, 1, 2, 3}));
}

// (A step on another grid is resampled onto the first's: moving_series_test.cpp.)
TEST(SeriesReader, AStepOnAnotherGridIsHeldOnTheFirstsATruncatedOneFailsNamingItsFile) {
  const auto dir = test::scratch();
  const auto pvd = writeSeries(dir, 4, 4);
  writeVti(dir / stepName(2), stepField(2, {5, 3, 2}));
  std::ifstream in(dir / stepName(3), std::ios::binary);
  const std::string whole((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  test::writeText(dir / stepName(3), whole.substr(0, whole.size() / 2));
  SeriesIndex index = indexSeries(pvd, {});
  auto reader = readerFor(index, 4, 2);
  EXPECT_EQ(reader->wait(2)->dims(), glm::ivec3(4, 3, 2));
  test::expectError([&] { reader->wait(3); }, {stepName(3)});
  expectStep(*reader->wait(1), 1);
}

}  // namespace
}  // namespace sandstorm
