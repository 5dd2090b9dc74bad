// parseAsciiNumbers: the values a serial parse reads, in place, over the cores;
// windows and parts kept small here so that a short text crosses many of each.
#include "core/io/ascii_numbers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStructuredPoints.h>
#include <vtkStructuredPointsReader.h>

#include "core/io/field_loader.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

constexpr AsciiWindows kSmall{.window = 997, .part = 61};

// `count` floats, each printed with %.9g (which reads back as the same
// float), between separators of every kind the format allows.
struct Numbers {
  std::vector<float> values;
  std::string text;
  std::vector<std::size_t> ends;  // the offset after each value
};
Numbers numbers(std::size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> normal(0.0f, 1000.0f);
  const char* separators[] = {" ", "\n", "\t", "\r\n", "  \n\n", " \f ", "\v"};
  Numbers n;
  n.text = "  \n";
  for (std::size_t i = 0; i < count; ++i) {
    const float v = i % 7 == 0 ? float(int(normal(rng))) : normal(rng) * (i % 3 ? 1e-6f : 1.0f);
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", double(v));
    n.values.push_back(v);
    n.text += buffer;
    n.ends.push_back(n.text.size());
    n.text += separators[rng() % std::size(separators)];
  }
  return n;
}

TEST(AsciiNumbers, EveryValueLandsInItsPlaceAcrossWindowsAndParts) {
  const Numbers n = numbers(20000, 1);
  std::vector<float> out(n.values.size(), -1.0f);
  std::vector<std::size_t> passed;
  const AsciiScan s = parseAsciiNumbers<float>(
      n.text, 0, out.size(), out.data(), [&](std::size_t at) { passed.push_back(at); }, kSmall);
  EXPECT_EQ(s.parsed, n.values.size());
  EXPECT_EQ(s.end, n.ends.back());
  EXPECT_EQ(out, n.values);
  ASSERT_GT(passed.size(), 100u) << "the text crosses many windows";
  for (std::size_t i = 1; i < passed.size(); ++i)
    EXPECT_GT(passed[i], passed[i - 1]);
  EXPECT_EQ(passed.back(), s.end);
}

TEST(AsciiNumbers, StopsAfterTheValuesAskedFor) {
  const Numbers n = numbers(5000, 2);
  for (const std::size_t asked : {std::size_t{1}, std::size_t{77}, std::size_t{4999}}) {
    std::vector<double> out(asked);
    const AsciiScan s = parseAsciiNumbers<double>(
        n.text, 0, asked, out.data(), [](std::size_t) {}, kSmall);
    EXPECT_EQ(s.parsed, asked);
    EXPECT_EQ(s.end, n.ends[asked - 1]);
    for (std::size_t i = 0; i < asked; ++i)
      ASSERT_EQ(float(out[i]), n.values[i]) << i;
  }
}

TEST(AsciiNumbers, StopsAtTheFirstTokenThatIsNoNumberOrAtTheEnd) {
  Numbers n = numbers(3000, 3);
  // Two bad tokens: the parse must stop at the first, value 2001.
  const std::size_t first = n.ends[1999] + 1, second = n.ends[2599] + 1;
  n.text.replace(second, 0, "zz ");
  n.text.replace(first, 0, "1.5.2 ");
  std::vector<float> out(3000, -1.0f);
  const AsciiScan s = parseAsciiNumbers<float>(
      n.text, 0, out.size(), out.data(), [](std::size_t) {}, kSmall);
  EXPECT_EQ(s.parsed, 2000u);
  EXPECT_EQ(n.text.substr(s.end, 6), "1.5.2 ");
  EXPECT_EQ(std::vector<float>(out.begin(), out.begin() + 2000),
            std::vector<float>(n.values.begin(), n.values.begin() + 2000));
  // Fewer values than asked: all of them, and the end after the last.
  const Numbers m = numbers(100, 4);
  std::vector<float> more(500);
  const AsciiScan t = parseAsciiNumbers<float>(
      m.text, 0, more.size(), more.data(), [](std::size_t) {}, kSmall);
  EXPECT_EQ(t.parsed, 100u);
  EXPECT_EQ(t.end, m.ends.back());
}

// A whole ASCII file, large enough to be parsed over the cores: the same
// floats as VTK's own legacy reader reads, and a bad value deep in it named
// with its line and its place, as the serial parse names it.
TEST(AsciiNumbers, AnAsciiFileLoadsAsVtksReaderReadsIt) {
  const auto path = test::scratch() / "ascii.vtk";
  const Numbers n = numbers(3 * 40 * 40 * 50, 5);
  const std::string header =
      "# vtk DataFile Version 3.0\nwind\nASCII\nDATASET STRUCTURED_POINTS\n"
      "DIMENSIONS 40 40 50\nORIGIN 0 0 0\nSPACING 1 1 1\nPOINT_DATA 80000\n"
      "VECTORS wind float\n";
  test::writeText(path, header + n.text + "\n");
  vtkNew<vtkStructuredPointsReader> vtk;
  vtk->SetFileName(path.c_str());
  vtk->Update();
  auto* expected = vtkFloatArray::SafeDownCast(vtk->GetOutput()->GetPointData()->GetVectors());
  ASSERT_NE(expected, nullptr);
  const VectorField f = loadField(path);
  ASSERT_EQ(f.dims(), glm::ivec3(40, 40, 50));
  std::size_t differ = 0;
  for (int k = 0; k < 50; ++k)
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i) {
        const vtkIdType p = (vtkIdType(k) * 40 + j) * 40 + i;
        const glm::vec3 want(expected->GetValue(3 * p), expected->GetValue(3 * p + 1),
                             expected->GetValue(3 * p + 2));
        differ += f.at(i, j, k) != want;
      }
  EXPECT_EQ(differ, 0u);

  std::string bad = header + n.text + "\n";
  const std::size_t at = header.size() + n.ends[200000] + 1;
  bad.replace(at, 0, "1e5x ");
  test::writeText(path, bad);
  const long long line = std::count(bad.begin(), bad.begin() + long(at), '\n') + 1;
  test::expectError(
      [&] { loadField(path); },
      {concat("ascii.vtk:", line, ": '1e5x'; expected vectors wind value 200002 of 240000")});
}

}  // namespace
}  // namespace sandstorm
