// VTK XML files are checked before VTK reads them: for every encoding VTK's
// own writers produce (ascii, inline base64, appended raw and base64, zlib or
// not, UInt32 or UInt64 headers, little or big endian), a good file passes and
// loads, and a file whose attributes claim more than its payload holds, or
// more than the memory budget, is refused with the file, the array and the
// numbers, before VTK allocates anything.
#include "core/io/vtk_xml_check.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkRectilinearGrid.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLStructuredGridWriter.h>

#include <cstring>
#include <regex>

#include "core/io/field_loader.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

struct Encoding {
  const char* name;
  int mode;  // vtkXMLWriter::Ascii, Binary, Appended
  bool base64Appended;
  int compressor;  // 0 none, 1 zlib, 2 LZ4, 3 LZMA
  bool header64, bigEndian;
};

const Encoding kEncodings[] = {
    {"ascii", 0, false, false, false, false},
    {"binary", 1, false, false, false, false},
    {"binary_zlib", 1, false, true, false, false},
    {"binary_uint64", 1, false, false, true, false},
    {"binary_zlib64", 1, false, true, true, false},
    {"raw", 2, false, false, false, false},
    {"raw_zlib", 2, false, true, false, false},
    {"raw_uint64", 2, false, false, true, false},
    {"base64", 2, true, false, false, false},
    {"base64_zlib", 2, true, true, false, false},
    {"raw_big_endian", 2, false, false, false, true},
    {"binary_zlib_big_endian", 1, false, true, true, true},
    {"binary_lz4", 1, false, 2, false, false},
    {"raw_lz4", 2, false, 2, false, false},
    {"base64_lzma", 2, true, 3, false, false},
    {"raw_lzma64", 2, false, 3, true, false},
};

vtkNew<vtkImageData> image() {
  vtkNew<vtkImageData> img;
  img->SetDimensions(4, 3, 2);
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(24);
  for (vtkIdType i = 0; i < 72; ++i)
    v->SetValue(i, float(i) * 0.25f);
  img->GetPointData()->SetVectors(v);
  return img;
}

template <class Writer>
void configure(Writer* w, const Encoding& e) {
  w->SetDataMode(e.mode);
  w->SetEncodeAppendedData(e.base64Appended);
  if (e.compressor == 1)
    w->SetCompressorTypeToZLib();
  else if (e.compressor == 2)
    w->SetCompressorTypeToLZ4();
  else if (e.compressor == 3)
    w->SetCompressorTypeToLZMA();
  else
    w->SetCompressorTypeToNone();
  if (e.header64)
    w->SetHeaderTypeToUInt64();
  else
    w->SetHeaderTypeToUInt32();
  if (e.bigEndian)
    w->SetByteOrderToBigEndian();
  else
    w->SetByteOrderToLittleEndian();
}

std::filesystem::path write(const std::filesystem::path& dir, const Encoding& e) {
  const auto path = dir / (std::string(e.name) + ".vti");
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(image());
  w->SetFileName(path.c_str());
  configure(w.Get(), e);
  w->Write();
  return path;
}

std::filesystem::path edited(const std::filesystem::path& path, const std::string& pattern,
                             const std::string& with, const std::string& suffix) {
  const std::string text = test::readAll(path);
  const std::string out = std::regex_replace(text, std::regex(pattern), with);
  EXPECT_NE(out, text) << pattern;
  auto to = path;
  to.replace_filename(path.stem().string() + "_" + suffix + ".vti");
  test::writeText(to, out);
  return to;
}

constexpr std::size_t kBudget = std::size_t{2} << 30;

class VtkXmlCheck : public testing::TestWithParam<Encoding> {};

TEST_P(VtkXmlCheck, AGoodFilePassesAndLoads) {
  const auto path = write(test::scratch(), GetParam());
  EXPECT_NO_THROW(checkVtkXml(path, kBudget));
  const VectorField f = loadField(path);
  EXPECT_EQ(f.at(3, 2, 1), glm::vec3(23 * 0.75f, 23 * 0.75f + 0.25f, 23 * 0.75f + 0.5f));
}

TEST_P(VtkXmlCheck, ComponentsBeyondTheBudgetAreRefusedBeforeVtkReads) {
  const auto path = write(test::scratch(), GetParam());
  const auto bad =
      edited(path, "NumberOfComponents=\"3\"", "NumberOfComponents=\"1000000000\"", "huge");
  test::expectError([&] { loadField(bad); }, {bad.string(), "DataArray 'velocity'",
                                              "1000000000 components", "memory budget"});
}

TEST_P(VtkXmlCheck, ComponentsThePayloadCannotHoldAreRefused) {
  const auto path = write(test::scratch(), GetParam());
  const auto bad =
      edited(path, "NumberOfComponents=\"3\"", "NumberOfComponents=\"100000\"", "short");
  test::expectError([&] { loadField(bad); },
                    {bad.string(), "DataArray 'velocity'", "100000 components need"});
}

TEST_P(VtkXmlCheck, ATupleCountThatIsNotTheExtentsIsRefused) {
  const auto path = write(test::scratch(), GetParam());
  const auto bad = edited(path, "NumberOfComponents=\"3\"",
                          "NumberOfComponents=\"3\" NumberOfTuples=\"999999\"", "tuples");
  test::expectError([&] { loadField(bad); }, {bad.string(), "NumberOfTuples 999999", "gives 24"});
}

// A cut file is refused, or (cut only in its closing tags) reads every value.
TEST_P(VtkXmlCheck, EveryTruncationIsRefusedOrReadWhole) {
  const auto path = write(test::scratch(), GetParam());
  const VectorField whole = loadField(path);
  const std::string text = test::readAll(path);
  const auto cut = path.parent_path() / "cut.vti";
  int refused = 0;
  for (std::size_t n = 0; n < text.size(); n += 7) {
    test::writeText(cut, text.substr(0, n));
    try {
      checkVtkXml(cut, kBudget);
      const VectorField part = loadField(cut);
      EXPECT_TRUE(std::equal(part.values().begin(), part.values().end(), whole.values().begin(),
                             whole.values().end()))
          << "a file cut at byte " << n << " of " << text.size() << " loaded other values";
    } catch (const Error&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, int(text.size() / 7) * 9 / 10);
}

// VTK's reader leaks what it was filling when a payload fails halfway (zlib
// errors, bad base64, values that are not numbers), so the check must refuse
// every damaged payload VTK would fail on. Each byte of the data is damaged in
// turn: the check refuses the file, or VTK reads it (other values, maybe).
TEST_P(VtkXmlCheck, DamagedDataIsRefusedUnlessVtkReadsIt) {
  const auto path = write(test::scratch(), GetParam());
  const std::string text = test::readAll(path);
  // The data: each inline DataArray's text, or the appended section.
  std::vector<std::size_t> bytes;
  const std::size_t appended = text.find("<AppendedData");
  if (appended != std::string::npos) {
    for (std::size_t i = text.find('_', appended) + 1; i < text.rfind("</AppendedData>"); ++i)
      bytes.push_back(i);
  } else {
    for (std::size_t at = text.find("<DataArray"); at != std::string::npos;
         at = text.find("<DataArray", at + 1))
      for (std::size_t i = text.find('>', at) + 1; text[i] != '<'; ++i)
        bytes.push_back(i);
  }
  const auto damaged = path.parent_path() / "damaged.vti";
  int refused = 0;
  for (std::size_t k = 0; k < bytes.size(); k += 3) {
    const std::size_t i = bytes[k];
    std::string bad = text;
    bad[i] = char(bad[i] ^ (GetParam().mode == 0 ? 0x04 : 0x5A));
    test::writeText(damaged, bad);
    try {
      checkVtkXml(damaged, kBudget);
    } catch (const Error&) {
      ++refused;
      continue;
    }
    try {
      loadField(damaged);
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find("VTK says"), std::string::npos)
          << "byte " << i << " damaged: the check passed, then VTK failed: " << what;
    }
  }
  EXPECT_GT(refused, 0);
}

INSTANTIATE_TEST_SUITE_P(Encodings, VtkXmlCheck, testing::ValuesIn(kEncodings),
                         [](const testing::TestParamInfo<Encoding>& i) { return i.param.name; });

TEST(VtkXmlCheckHeaders, ACompressionHeaderListingEndlessBlocksIsRefused) {
  const auto dir = test::scratch();
  const auto path = write(dir, kEncodings[6]);  // appended raw, zlib, UInt32
  std::string text = test::readAll(path);
  const std::size_t data = text.find('_', text.find("<AppendedData")) + 1;
  // The first header word is the block count: two thousand million blocks.
  text[data] = '\x00', text[data + 1] = '\x94', text[data + 2] = '\x35', text[data + 3] = '\x77';
  test::writeText(path, text);
  test::expectError([&] { checkVtkXml(path, kBudget); },
                    {path.string(), "2000000000 compressed blocks", "memory budget"});
}

// VTK looks for an array's inline data after the first '>' past its tag's
// start, even one inside a quoted value, and would decode the attribute's
// tail as a compression header (a fuzzer's file asked for 14 GB so).
TEST(VtkXmlCheckHeaders, AQuotedGreaterThanInAnInlineArraysTagIsRefused) {
  const auto dir = test::scratch();
  const auto path = write(dir, kEncodings[2]);  // inline base64, zlib
  std::string text = test::readAll(path);
  const std::size_t tag = text.find("<DataArray");
  ASSERT_NE(tag, std::string::npos);
  text.insert(tag + 10, " Note=\"0>70710678118654\"");
  test::writeText(path, text);
  test::expectError([&] { checkVtkXml(path, kBudget); }, {path.string(), "'>'", "&gt;"});
  test::expectError([&] { loadField(path); }, {path.string(), "'>'"});
}

TEST(VtkXmlCheckHeaders, AnUncompressedByteCountBeyondThePayloadIsRefused) {
  const auto dir = test::scratch();
  const auto path = write(dir, kEncodings[5]);  // appended raw, UInt32
  std::string text = test::readAll(path);
  const std::size_t data = text.find('_', text.find("<AppendedData")) + 1;
  text.resize(data + 100);  // the header says 288 bytes; 96 follow it
  text += "\n</AppendedData>\n</VTKFile>\n";
  test::writeText(path, text);
  test::expectError([&] { checkVtkXml(path, kBudget); },
                    {path.string(), "truncated", "declares 288 bytes", "follow it"});
}

TEST(VtkXmlCheckHeaders, ASmallBudgetRefusesAGoodFileSayingSo) {
  const auto path = write(test::scratch(), kEncodings[5]);
  test::expectError([&] { checkVtkXml(path, 100); },
                    {"288 bytes", "memory budget (field.memory_budget) of 100"});
}

TEST(VtkXmlCheckGrids, RectilinearAndStructuredGridsPassAndTheirCoordinatesAreChecked) {
  const auto dir = test::scratch();
  vtkNew<vtkRectilinearGrid> r;
  r->SetDimensions(3, 2, 2);
  for (int a = 0; a < 3; ++a) {
    vtkNew<vtkFloatArray> c;
    const int n = a == 0 ? 3 : 2;
    c->SetNumberOfTuples(n);
    for (int i = 0; i < n; ++i)
      c->SetValue(i, float(i));
    if (a == 0) r->SetXCoordinates(c);
    if (a == 1) r->SetYCoordinates(c);
    if (a == 2) r->SetZCoordinates(c);
  }
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(12);
  v->Fill(1.0f);
  r->GetPointData()->SetVectors(v);
  const auto vtr = dir / "grid.vtr";
  vtkNew<vtkXMLRectilinearGridWriter> rw;
  rw->SetInputData(r);
  rw->SetFileName(vtr.c_str());
  rw->SetDataModeToAscii();
  rw->Write();
  EXPECT_NO_THROW(checkVtkXml(vtr, kBudget));
  // The x coordinates claim four values where the extent has three points along x.
  const std::string text = test::readAll(vtr);
  const std::size_t coordinates = text.find("<Coordinates>");
  const std::size_t values = text.find(">", text.find("<DataArray", coordinates)) + 1;
  test::writeText(vtr, text.substr(0, values) + " 7 " + text.substr(values));
  test::expectError([&] { checkVtkXml(vtr, kBudget); },
                    {vtr.string(), "Coordinates DataArray", "holds 4 ascii values", "need 3"});

  vtkNew<vtkStructuredGrid> s;
  s->SetDimensions(2, 2, 2);
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 8; ++i)
    points->InsertNextPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  s->SetPoints(points);
  v->SetNumberOfTuples(8);
  s->GetPointData()->SetVectors(v);
  const auto vts = dir / "grid.vts";
  vtkNew<vtkXMLStructuredGridWriter> sw;
  sw->SetInputData(s);
  sw->SetFileName(vts.c_str());
  sw->Write();
  EXPECT_NO_THROW(checkVtkXml(vts, kBudget));
}

TEST(VtkXmlCheckText, MalformedXmlIsRefused) {
  const auto dir = test::scratch();
  const auto path = dir / "bad.vti";
  const auto errorOf = [&](const std::string& text) {
    test::writeText(path, text);
    try {
      checkVtkXml(path, kBudget);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(errorOf("<VTKFile type=\"ImageData\"><ImageData").find("truncated inside a tag"),
            std::string::npos);
  EXPECT_NE(errorOf("<VTKFile><ImageData></VTKFile>").find("does not match"), std::string::npos);
  EXPECT_NE(errorOf("<VTKFile header_type=\"UInt16\">").find("header_type"), std::string::npos);
  EXPECT_NE(errorOf("<VTKFile><Piece Extent=\"0 1 0 1\">").find("six whole numbers"),
            std::string::npos);
  EXPECT_NE(errorOf("<VTKFile><Piece Extent=\"0 1 0 1 0 1\"><PointData><DataArray type=\"String\">")
                .find("not a numeric type"),
            std::string::npos);
  EXPECT_NE(errorOf("<VTKFile><Piece Extent=\"0 1 0 1 0 1\"><PointData><DataArray "
                    "type=\"Float32\" format=\"binary\">!!!!</DataArray>")
                .find("not valid base64"),
            std::string::npos);
  EXPECT_NE(errorOf("<VTKFile><Piece Extent=\"0 1 0 1 0 1\"><PointData><DataArray "
                    "type=\"Float32\" format=\"appended\" offset=\"0\"/></PointData></Piece>"
                    "</VTKFile>")
                .find("no AppendedData"),
            std::string::npos);
  EXPECT_NE(errorOf("junk").find("not XML"), std::string::npos);
}

namespace sandstorm {
namespace {

TEST(VtkXmlCheckValues, AsciiValuesThatAreNotNumbersOfTheTypeAreRefused) {
  const auto path = write(test::scratch(), kEncodings[0]);
  const auto word = edited(path, ">\\s*0 0.25 0.5", ">\n0 2(-1 0.5", "word");
  test::expectError([&] { checkVtkXml(word, kBudget); },
                    {word.string(), "DataArray 'velocity'", "ascii value 2", "'2(-1'",
                     "not a finite Float32 number"});
  const auto huge = edited(path, ">\\s*0 0.25 0.5", ">\n0 1e39 0.5", "huge");
  test::expectError([&] { checkVtkXml(huge, kBudget); }, {"'1e39'", "Float32"});
  const auto nan = edited(path, ">\\s*0 0.25 0.5", ">\n0 nan 0.5", "nan");
  test::expectError([&] { checkVtkXml(nan, kBudget); }, {"'nan'", "not a finite"});
}

TEST(VtkXmlCheckValues, APieceOutsideTheWholeExtentIsRefused) {
  const auto path = write(test::scratch(), kEncodings[5]);
  const auto bad = edited(path, "WholeExtent=\"0 3", "WholeExtent=\"1 3", "outside");
  test::expectError(
      [&] { checkVtkXml(bad, kBudget); },
      {bad.string(), "Piece 1 Extent '0 3 0 2 0 1'", "outside the WholeExtent", "along x"});
}

TEST(VtkXmlCheckValues, AnUnknownCompressorIsRefused) {
  const auto path = write(test::scratch(), kEncodings[6]);
  const auto bad = edited(path, "vtkZLibDataCompressor", "vtkZstdDataCompressor", "zstd");
  test::expectError([&] { checkVtkXml(bad, kBudget); },
                    {bad.string(), "compressor 'vtkZstdDataCompressor'", "vtkLZ4DataCompressor"});
}

TEST(VtkXmlCheckValues, ACorruptCompressedBlockIsRefused) {
  for (int e : {6, 13}) {  // appended raw: zlib, LZ4
    const auto path = write(test::scratch(), kEncodings[e]);
    std::string text = test::readAll(path);
    // The block starts after the 16-byte header; its middle is overwritten.
    const std::size_t data = text.find('_', text.find("<AppendedData")) + 1 + 16;
    for (std::size_t i = 4; i < 12; ++i)
      text[data + i] = '\xff';
    test::writeText(path, text);
    test::expectError([&] { checkVtkXml(path, kBudget); },
                      {path.string(), "DataArray 'velocity'", "compressed block 1 of 1"});
  }
}

// Compressed blocks are checked in batches over the cores: of two bad blocks
// the first is named, in the first batch or a later one, and a file of
// several batches passes whole.

// Appended raw zlib data of side^3 vectors that hardly compress (a hash of
// the index), in blocks of `blockSize` bytes.
std::filesystem::path incompressible(const std::string& name, int side, int blockSize) {
  vtkNew<vtkImageData> img;
  img->SetDimensions(side, side, side);
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(vtkIdType(side) * side * side);
  std::uint32_t h = 2166136261u;
  for (vtkIdType i = 0; i < v->GetNumberOfValues(); ++i) {
    h = (h ^ std::uint32_t(i)) * 16777619u;
    v->SetValue(i, float(h >> 8) * 0x1p-24f);
  }
  img->GetPointData()->SetVectors(v);
  const auto path = test::scratch() / (name + ".vti");
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(img);
  w->SetFileName(path.c_str());
  configure(w.Get(), kEncodings[6]);  // appended raw, zlib, UInt32
  w->SetBlockSize(blockSize);
  EXPECT_EQ(w->Write(), 1);
  return path;
}

// Overwrites the middle of each of `damaged` (0-based) blocks.
void damage(const std::filesystem::path& path, std::initializer_list<std::size_t> damaged) {
  std::string text = test::readAll(path);
  const std::size_t data = text.find('_', text.find("<AppendedData")) + 1;
  auto word = [&](std::size_t at) {
    std::uint32_t w;
    std::memcpy(&w, text.data() + at, 4);
    return std::size_t(w);
  };
  const std::size_t count = word(data);
  std::vector<std::size_t> start(count + 1, data + 4 * (3 + count));
  for (std::size_t b = 0; b < count; ++b)
    start[b + 1] = start[b] + word(data + 4 * (3 + b));
  for (std::size_t b : damaged) {
    ASSERT_LT(b, count);
    for (std::size_t i = start[b] + 2; i < start[b + 1] - 2; ++i)
      text[i] = char(~text[i]);
  }
  test::writeText(path, text);
}

TEST(VtkXmlCheckBlocks, OfTwoBadBlocksTheFirstIsNamed) {
  const auto path = incompressible("two_bad_blocks", 12, 256);  // 81 blocks, 20736 bytes
  ASSERT_NO_THROW(checkVtkXml(path, kBudget));
  damage(path, {2, 8});
  test::expectError([&] { checkVtkXml(path, kBudget); },
                    {path.string(), "DataArray 'velocity'", "compressed block 3 of 81"});
}

TEST(VtkXmlCheckBlocks, AFileOfSeveralBatchesPassesAndABadBlockInALaterOneIsNamed) {
  // 24 MiB in 1 MiB blocks, compressed little: two batches of 16 MiB.
  const auto path = incompressible("batches", 128, 1 << 20);
  ASSERT_NO_THROW(checkVtkXml(path, kBudget));
  EXPECT_GT(std::filesystem::file_size(path), std::uintmax_t{18} << 20);
  damage(path, {22, 23});
  test::expectError([&] { checkVtkXml(path, kBudget); },
                    {path.string(), "compressed block 23 of 24"});
}

}  // namespace
}  // namespace sandstorm

// VTK's reader decodes an array's base64 as one unbroken run: a space inside
// it (inline or appended) is refused before VTK fails on it halfway (and
// leaks; found by fuzz_field_vtu); spaces around inline data are fine.
TEST(VtkXmlCheckValues, WhitespaceInsideBase64IsRefusedAndAroundItAccepted) {
  const auto inlined = write(test::scratch(), kEncodings[1]);  // inline base64
  const std::string text = test::readAll(inlined);
  const std::size_t tag = text.find('>', text.find("Name=\"velocity\""));
  const std::size_t data = text.find_first_not_of(" \t\r\n", tag + 1);
  auto with = [&](const std::string& t, const std::string& name) {
    const auto path = test::scratch() / name;
    test::writeText(path, t);
    return path;
  };
  const auto around = with(text.substr(0, data) + "\n \t" + text.substr(data), "around.vti");
  EXPECT_NO_THROW(checkVtkXml(around, kBudget));
  EXPECT_NO_THROW(loadField(around));
  const auto inside = with(text.substr(0, data + 8) + "\n" + text.substr(data + 8), "inside.vti");
  test::expectError([&] { checkVtkXml(inside, kBudget); },
                    {inside.string(), "DataArray 'velocity'", "whitespace inside the base64"});

  const auto appended = write(test::scratch(), kEncodings[8]);  // appended base64
  const std::string a = test::readAll(appended);
  const std::size_t start = a.find('_', a.find("<AppendedData")) + 1;
  const auto broken = with(a.substr(0, start + 12) + " " + a.substr(start + 12), "broken.vti");
  test::expectError([&] { checkVtkXml(broken, kBudget); },
                    {broken.string(), "whitespace inside the base64"});
}

}  // namespace
}  // namespace sandstorm
