// FieldSequence: frames from a .pvd or a numbered pattern, linear in time.
#include <gtest/gtest.h>

#include <cstdio>

#include "core/io/field_loader.h"
#include "core/io/field_sequence.h"
#include "core/io/vti_writer.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

VectorField frameField(float scale, glm::ivec3 dims = {3, 3, 2}) {
  VectorField f(Box{{0, 0, 0}, {2, 2, 1}}, dims);
  for (std::size_t i = 0; i < f.pointCount(); ++i)
    f.values()[i] = scale * glm::vec3(float(i), 1.0f, -0.5f * float(i));
  return f;
}

std::filesystem::path writeSeries(const std::filesystem::path& dir, int frames) {
  std::string pvd =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (int n = 0; n < frames; ++n) {
    char name[32];
    std::snprintf(name, sizeof(name), "step_%03d.vti", n);
    writeVti(dir / name, frameField(float(n + 1)));
    pvd += "  <DataSet timestep=\"" + std::to_string(0.5 * n) + "\" part=\"0\" file=\"" + name +
           "\"/>\n";
  }
  pvd += "</Collection>\n</VTKFile>\n";
  test::writeText(dir / "series.pvd", pvd);
  return dir / "series.pvd";
}

TEST(FieldSequence, MidpointIsTheAverageOfTheFrames) {
  const auto dir = test::scratch();
  const FieldSequence s = FieldSequence::fromPvd(writeSeries(dir, 4));
  ASSERT_EQ(s.size(), 4u);
  EXPECT_DOUBLE_EQ(s.startTime(), 0.0);
  EXPECT_DOUBLE_EQ(s.endTime(), 1.5);
  const VectorField mid = s.at(0.75);  // between frames 1 (t = 0.5) and 2 (t = 1.0)
  const FrameBlend b = s.blendAt(0.75);
  EXPECT_EQ(b.first, 1u);
  EXPECT_EQ(b.second, 2u);
  EXPECT_FLOAT_EQ(b.weight, 0.5f);
  for (std::size_t i = 0; i < mid.pointCount(); ++i) {
    const glm::vec3 avg = 0.5f * (s.frame(1).values()[i] + s.frame(2).values()[i]);
    EXPECT_NEAR(glm::length(mid.values()[i] - avg), 0.0f, 1e-5f);
  }
  const glm::vec3 p(0.7f, 1.3f, 0.4f);
  EXPECT_NEAR(glm::length(s.sample(p, 0.75) - 0.5f * (s.frame(1).sample(p) + s.frame(2).sample(p))),
              0.0f, 1e-5f);
  // At a frame's own time, that frame exactly.
  EXPECT_EQ(s.at(0.5).values()[5], s.frame(1).values()[5]);
}

TEST(FieldSequence, ClampsOrLoops) {
  const auto dir = test::scratch();
  FieldSequence s = FieldSequence::fromPvd(writeSeries(dir, 3));  // t = 0, 0.5, 1
  EXPECT_EQ(s.blendAt(-3.0).first, 0u);
  EXPECT_EQ(s.blendAt(7.0).first, 2u);
  EXPECT_FLOAT_EQ(s.blendAt(7.0).weight, 0.0f);
  s.setPlayback(Playback::Loop);
  const FrameBlend b = s.blendAt(2.25);  // 2.25 wraps to 0.25
  EXPECT_EQ(b.first, 0u);
  EXPECT_EQ(b.second, 1u);
  EXPECT_FLOAT_EQ(b.weight, 0.5f);
  const FrameBlend c = s.blendAt(-0.25);  // wraps to 0.75
  EXPECT_EQ(c.first, 1u);
  EXPECT_FLOAT_EQ(c.weight, 0.5f);
}

TEST(FieldSequence, FromANumberedPattern) {
  const auto dir = test::scratch();
  writeSeries(dir, 5);
  const FieldSequence s = FieldSequence::fromPattern((dir / "step_%03d.vti").string(), 10.0, 0.25);
  ASSERT_EQ(s.size(), 5u);
  EXPECT_DOUBLE_EQ(s.time(4), 11.0);
  test::expectError([&] { FieldSequence::fromPattern((dir / "step_%s.vti").string(), 0, 1); },
                    {"step_%s.vti", "integer conversion"});
  test::expectError([&] { FieldSequence::fromPattern((dir / "none_%d.vti").string(), 0, 1); },
                    {"none_0.vti"});
  test::expectError([&] { FieldSequence::fromPattern((dir / "step_%03d.vti").string(), 0, 0); },
                    {"dt > 0"});
}

TEST(FieldSequence, FramesMustShareTheGrid) {
  const auto dir = test::scratch();
  const auto pvd = writeSeries(dir, 3);
  writeVti(dir / "step_002.vti", frameField(1.0f, {4, 3, 2}));
  test::expectError([&] { FieldSequence::fromPvd(pvd); },
                    {pvd.string(), "step_002.vti", "same grid"});
  test::expectError(
      [&] {
        FieldSequence({0.0, 1.0}, {frameField(1.0f), frameField(1.0f, {3, 3, 3})});
      },
      {"frame 1", "same grid"});
  test::expectError(
      [&] {
        FieldSequence({1.0, 1.0}, {frameField(1.0f), frameField(2.0f)});
      },
      {"does not come after"});
}

TEST(FieldSequence, PvdErrorsNameTheCollection) {
  const auto dir = test::scratch();
  const auto pvd = dir / "bad.pvd";
  test::writeText(pvd, "<VTKFile type=\"Collection\"><Collection></Collection></VTKFile>");
  test::expectError([&] { FieldSequence::fromPvd(pvd); }, {pvd.string(), "lists no <DataSet>"});
  test::writeText(pvd,
                  "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"x\" "
                  "file=\"a.vti\"/></Collection></VTKFile>");
  test::expectError([&] { FieldSequence::fromPvd(pvd); }, {pvd.string(), "is not a number"});
  test::writeText(pvd,
                  "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"0\" "
                  "file=\"gone.vti\"/></Collection></VTKFile>");
  test::expectError([&] { FieldSequence::fromPvd(pvd); }, {"gone.vti", "no such file"});
  test::writeText(pvd, "<VTKFile type=\"Collection\"><Collection><DataSet");
  test::expectError([&] { FieldSequence::fromPvd(pvd); }, {pvd.string()});
  // loadField() on a .pvd gives its first frame.
  const auto good = writeSeries(dir, 2);
  LoadReport report;
  EXPECT_EQ(loadField(good, {}, &report).values()[4], frameField(1.0f).values()[4]);
  EXPECT_FALSE(report.notes.empty());
}

}  // namespace
}  // namespace sandstorm
