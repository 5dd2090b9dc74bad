// Malformed input of every kind: a clear Error naming the file and what was
// expected, never a crash, never a huge allocation, never silent garbage.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <regex>

#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStructuredPointsWriter.h>
#include <vtkXMLImageDataWriter.h>

#include "core/io/field_loader.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

using test::expectError;

vtkNew<vtkImageData> smallImage(bool withVectors = true) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(3, 4, 2);
  image->SetSpacing(1.0, 0.5, 2.0);
  vtkNew<vtkFloatArray> p;
  p->SetName("pressure");
  p->SetNumberOfTuples(24);
  p->Fill(1.0f);
  image->GetPointData()->SetScalars(p);
  if (withVectors) {
    vtkNew<vtkFloatArray> v;
    v->SetName("velocity");
    v->SetNumberOfComponents(3);
    v->SetNumberOfTuples(24);
    v->Fill(0.5f);
    image->GetPointData()->SetVectors(v);
  }
  return image;
}

std::string legacyAscii(const std::filesystem::path& dir, bool withVectors = true) {
  const auto path = dir / "base.vtk";
  vtkNew<vtkStructuredPointsWriter> w;
  w->SetInputData(smallImage(withVectors));
  w->SetFileName(path.c_str());
  w->SetFileTypeToASCII();
  w->Write();
  return test::readAll(path);
}

std::string xmlAscii(const std::filesystem::path& dir) {
  const auto path = dir / "base.vti";
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(smallImage());
  w->SetFileName(path.c_str());
  w->SetDataModeToAscii();
  w->Write();
  return test::readAll(path);
}

std::string replaced(std::string text, const std::string& pattern, const std::string& with) {
  const std::string out = std::regex_replace(text, std::regex(pattern), with);
  EXPECT_NE(out, text) << "pattern " << pattern << " not found";
  return out;
}

TEST(BadInput, LegacyDimensionsZeroNegativeOrOverflowing) {
  const auto dir = test::scratch();
  const std::string base = legacyAscii(dir);
  const auto path = dir / "bad.vtk";
  test::writeText(path, replaced(base, "DIMENSIONS 3 4 2", "DIMENSIONS 3 0 2"));
  expectError([&] { loadField(path); }, {path.string(), "DIMENSIONS along y is 0", "positive"});
  test::writeText(path, replaced(base, "DIMENSIONS 3 4 2", "DIMENSIONS 3 4 -2"));
  expectError([&] { loadField(path); }, {path.string(), "DIMENSIONS along z is -2"});
  test::writeText(path, replaced(base, "DIMENSIONS 3 4 2", "DIMENSIONS 3000000 4000000 2000000"));
  expectError([&] { loadField(path); }, {path.string(), "memory budget"});
  test::writeText(path, replaced(base, "DIMENSIONS 3 4 2", "DIMENSIONS 99999999999 1 1"));
  expectError([&] { loadField(path); }, {path.string()});
}

TEST(BadInput, LegacyValueCountDiffersFromPointCount) {
  const auto dir = test::scratch();
  const auto path = dir / "bad.vtk";
  test::writeText(path, replaced(legacyAscii(dir), "POINT_DATA 24", "POINT_DATA 20"));
  expectError([&] { loadField(path); }, {path.string(), "POINT_DATA 20", "24"});
  test::writeText(path, replaced(legacyAscii(dir), "POINT_DATA 24", "POINT_DATA 2000000000"));
  expectError([&] { loadField(path); }, {path.string(), "POINT_DATA 2000000000"});
  // Fewer values than declared: VTK only warns; we refuse.
  std::string text = legacyAscii(dir);
  const auto vectors = text.find("VECTORS");
  test::writeText(path, text.substr(0, vectors + (text.size() - vectors) / 2));
  expectError([&] { loadField(path); }, {path.string()});
}

// Two arrays of one name in a section: VTK keeps the last, so the first
// would vanish unsaid. The same name in point and cell data is fine.
TEST(BadInput, LegacyArraysOfOneNameInASection) {
  const auto dir = test::scratch();
  const auto path = dir / "bad.vtk";
  test::writeText(path, replaced(legacyAscii(dir), "SCALARS pressure", "SCALARS velocity"));
  expectError([&] { loadField(path); },
              {path.string(), "a second array named 'velocity'", "names of their own"});
}

TEST(BadInput, SpacingZeroOrNegative) {
  const auto dir = test::scratch();
  const auto legacy = dir / "bad.vtk";
  test::writeText(legacy, replaced(legacyAscii(dir), "SPACING 1 0.5 2", "SPACING 1 0 2"));
  expectError([&] { loadField(legacy); }, {legacy.string(), "SPACING along y is 0", "positive"});
  test::writeText(legacy, replaced(legacyAscii(dir), "SPACING 1 0.5 2", "SPACING -1 0.5 2"));
  expectError([&] { loadField(legacy); }, {legacy.string(), "SPACING along x is -1"});
  const auto xml = dir / "bad.vti";
  test::writeText(xml, replaced(xmlAscii(dir), "Spacing=\"1 0.5 2\"", "Spacing=\"1 0.5 0\""));
  expectError([&] { loadField(xml); }, {xml.string(), "spacing along z is 0", "positive"});
  test::writeText(xml, replaced(xmlAscii(dir), "Spacing=\"1 0.5 2\"", "Spacing=\"1 -0.5 2\""));
  expectError([&] { loadField(xml); }, {xml.string(), "spacing along y is -0.5"});
}

TEST(BadInput, XmlExtentsEmptyOrHuge) {
  const auto dir = test::scratch();
  const auto xml = dir / "bad.vti";
  const std::string base = xmlAscii(dir);
  test::writeText(xml, replaced(base, "WholeExtent=\"0 2 0 3 0 1\"",
                                "WholeExtent=\"0 99999 0 99999 0 99999\""));
  // Its piece holds a sliver of it: refused before anything is allocated.
  expectError([&] { loadField(xml); },
              {xml.string(), "WholeExtent '0 99999 0 99999 0 99999'", "points without data"});
  test::writeText(xml,
                  replaced(base, "WholeExtent=\"0 2 0 3 0 1\"", "WholeExtent=\"0 2 0 -3 0 1\""));
  expectError([&] { loadField(xml); }, {xml.string()});
  // The extent claims fewer points than the values the file holds: VTK alone
  // would read a prefix of the data.
  test::writeText(
      xml, replaced(replaced(base, "WholeExtent=\"0 2 0 3 0 1\"", "WholeExtent=\"0 2 0 2 0 1\""),
                    "Extent=\"0 2 0 3 0 1\"", "Extent=\"0 2 0 2 0 1\""));
  expectError([&] { loadField(xml); },
              {xml.string(), "holds 24 ascii values", "need 18", "disagree"});
  const auto appended = dir / "appended.vti";
  {
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(smallImage());
    w->SetFileName(appended.c_str());
    w->Write();
  }
  test::writeText(appended,
                  replaced(replaced(test::readAll(appended), "WholeExtent=\"0 2 0 3 0 1\"",
                                    "WholeExtent=\"0 2 0 2 0 1\""),
                           "Extent=\"0 2 0 3 0 1\"", "Extent=\"0 2 0 2 0 1\""));
  expectError([&] { loadField(appended); }, {appended.string(), "declares 96 bytes", "need 72"});
}

TEST(BadInput, ScalarArrayWhereVectorsWereAsked) {
  const auto dir = test::scratch();
  const auto path = dir / "scalars.vtk";
  test::writeText(path, legacyAscii(dir, false));
  expectError([&] { loadField(path); },
              {path.string(), "no 3-component (vector) array", "'pressure' (1 component)"});
  LoadOptions o;
  o.arrayName = "pressure";
  expectError([&] { loadField(path, o); }, {path.string(), "'pressure' has 1 component"});
}

TEST(BadInput, LegacyDatasetOfAnotherKind) {
  const auto dir = test::scratch();
  const auto path = dir / "graph.vtk";
  test::writeText(path,
                  "# vtk DataFile Version 3.0\nx\nASCII\nDATASET GRAPH\nPOINTS 1 float\n0 0 0\n");
  expectError([&] { loadField(path); },
              {path.string(), ":4", "GRAPH", "expected STRUCTURED_POINTS", "POLYDATA"});
  test::writeText(path, "# vtk DataFile Version 3.0\nx\nTEXT\nDATASET STRUCTURED_POINTS\n");
  expectError([&] { loadField(path); }, {path.string(), ":3", "expected ASCII or BINARY"});
}

TEST(BadInput, WrongExtensions) {
  const auto dir = test::scratch();
  const auto vti = dir / "really_legacy.vti";
  test::writeText(vti, legacyAscii(dir));
  expectError([&] { loadField(vti); }, {vti.string(), "is a legacy VTK file", "not a VTK XML"});
  const auto vtk = dir / "really_xml.vtk";
  test::writeText(vtk, xmlAscii(dir));
  expectError([&] { loadField(vtk); }, {vtk.string(), "is a VTK XML image data file"});
  const auto vdb = dir / "text.vdb";
  test::writeText(vdb, "hello, this is not a volume\n");
  expectError([&] { loadField(vdb); }, {vdb.string(), "is not an OpenVDB file"});
  const auto empty = dir / "empty.vti";
  test::writeText(empty, "");
  expectError([&] { loadField(empty); },
              {empty.string(), "is empty: expected a VTK XML image data file (.vti)"});
  const auto exodus = dir / "text.e";
  test::writeText(exodus, "hello, this is not a mesh\n");
  expectError([&] { loadField(exodus); }, {exodus.string(), "is not an Exodus II"});
  const auto unknown = dir / "mystery.dat";
  test::writeText(unknown, "\x01\x02\x03 binary junk");
  expectError([&] { loadField(unknown); }, {unknown.string(), "format not recognised"});
  expectError([&] { loadField(dir / "missing.vti"); }, {"missing.vti", "no such file"});
}

TEST(BadInput, FgaMalformed) {
  const auto dir = test::scratch();
  const auto path = dir / "bad.fga";
  const std::string bounds = "0,0,0,\n1,1,1,\n";
  test::writeText(path, "0,1,1,\n" + bounds + "1,2,3,\n");
  expectError([&] { loadField(path); }, {path.string(), ":1", "dimension x is 0"});
  test::writeText(path, "2,-1,1,\n" + bounds + "1,2,3,\n");
  expectError([&] { loadField(path); }, {path.string(), "dimension y is -1"});
  test::writeText(path, "100000,100000,100000,\n" + bounds + "1,2,3,\n");
  expectError([&] { loadField(path); }, {path.string(), "memory budget"});
  test::writeText(path, "2,2,2,\n" + bounds + "1,2,3,\n");  // 1 of 8 vectors
  expectError([&] { loadField(path); }, {path.string(), "cannot fit"});
  std::string eight;
  for (int i = 0; i < 8; ++i)
    eight += "1,2,3,\n";
  test::writeText(path, "2,2,2,\n" + bounds + eight + "4,5,6,\n");
  expectError([&] { loadField(path); }, {path.string(), ":12", "more than the 8 vectors"});
  test::writeText(path, "2,2,2,\n" + bounds + eight.substr(0, eight.size() - 2));
  expectError([&] { loadField(path); }, {path.string(), "ends inside a number"});
  test::writeText(path, "2,2,2,\n" + bounds + eight.substr(0, eight.size() - 8) + "1,2,");
  expectError([&] { loadField(path); }, {path.string(), "7 complete vectors", "truncated"});
  test::writeText(path, "2,2,2,\n" + bounds + "1,2,x3,\n" + eight);
  expectError([&] { loadField(path); }, {path.string(), ":4", "'x3' is not a number"});
  test::writeText(path, "2,2,2,\n0,0,0,\n1,0,1,\n" + eight);
  expectError([&] { loadField(path); }, {path.string(), "bounds along y", "max > min"});
  test::writeText(path, "2,2,2,\n" + bounds + "nan,0,0,\ninf,0,0,\n" + eight.substr(14));
  LoadReport report;
  LoadOptions raw;
  raw.convertEngineAxes = false;
  const VectorField f = loadField(path, raw, &report);
  EXPECT_EQ(report.nonFinite, 2u);
  EXPECT_EQ(f.values()[0], glm::vec3(0.0f));
}

TEST(BadInput, UnityVfMalformed) {
  const auto dir = test::scratch();
  const auto path = dir / "bad.vf";
  auto header = [](const char* magic, std::uint16_t x, std::uint16_t y, std::uint16_t z) {
    std::string s(magic, 4);
    for (std::uint16_t d : {x, y, z})
      s.append(reinterpret_cast<const char*>(&d), 2);
    return s;
  };
  test::writeText(path, header("VF_F", 2, 2, 2) + std::string(32, '\0'));
  expectError([&] { loadField(path); }, {path.string(), "scalar", "VF_V"});
  test::writeText(path, header("VF_V", 2, 0, 2));
  expectError([&] { loadField(path); }, {path.string(), "dimension y is 0"});
  test::writeText(path, header("VF_V", 2, 2, 2) + std::string(96 + 12, '\0'));
  expectError([&] { loadField(path); }, {path.string(), "value count differs"});
  test::writeText(path, header("VF_V", 65535, 65535, 65535) + std::string(96, '\0'));
  expectError([&] { loadField(path); }, {path.string(), "truncated"});
}

TEST(BadInput, ResolutionMustBePositiveAndFit) {
  const auto dir = test::scratch();
  const auto path = dir / "ok.vtk";
  test::writeText(path, legacyAscii(dir));
  LoadOptions o;
  o.resolution = {4, 0, 4};
  expectError([&] { loadField(path, o); }, {path.string(), "field.resolution along y is 0"});
  o.resolution = {100000, 100000, 100000};
  expectError([&] { loadField(path, o); }, {path.string(), "memory budget"});
}

// A legacy file wrong after megabytes of BINARY values, whose text the parse
// has given back by then (PageBuffer): the error still names its line,
// counted here from the file's own bytes.
TEST(BadInput, ALegacyFileWrongPastItsFirstMegabytesNamesItsLine) {
  const auto path = test::scratch() / "bad.vtk";
  constexpr long long kPoints = 128 * 128 * 128;  // 24 MiB of vectors
  std::string text =
      "# vtk DataFile Version 3.0\nwind\nBINARY\nDATASET STRUCTURED_POINTS\n"
      "DIMENSIONS 128 128 128\nORIGIN 0 0 0\nSPACING 1 1 1\nPOINT_DATA 2097152\n"
      "VECTORS wind float\n";
  for (long long i = 0; i < 3 * kPoints; ++i) {
    const std::uint32_t u = std::bit_cast<std::uint32_t>(float(i % 977) - 400.0f);
    const char big[4] = {char(u >> 24), char(u >> 16), char(u >> 8), char(u)};
    text.append(big, 4);
  }
  text += "\n";
  const long long line = std::count(text.begin(), text.end(), '\n') + 1;
  text += "FIELD_DAT x 1\n";
  test::writeText(path, text);
  try {
    loadField(path);
    FAIL() << "loaded";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(concat("bad.vtk:", line, ": 'FIELD_DAT'")), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace sandstorm
