// HugePageImageReader (core/io/huge_page_image_reader.h): VTK's .vti reader
// with its large point arrays advised for transparent huge pages, and those
// the file holds raw copied from it over the cores. It must read exactly
// what vtkXMLImageDataReader reads, whichever way an array is stored; the
// array's memory must carry the advice (the kernel's smaps says the region
// may take huge pages) wherever the kernel has them at all.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>

#include "core/io/vtk_xml_check.h"

#include "core/io/huge_page_image_reader.h"
#include "core/io/vtk_message_trap.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

constexpr int kSide = 150;  // 150^3 x 12 bytes: 40.5 MB, past the 32 MiB the reader advises from

std::filesystem::path writeImage(const std::filesystem::path& path) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(kSide, kSide, kSide);
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(vtkIdType(kSide) * kSide * kSide);
  for (vtkIdType i = 0; i < v->GetNumberOfTuples(); ++i)
    v->SetTuple3(i, double(i % 97) * 0.25, -double(i % 13), 1.0 / double(1 + i % 7));
  image->GetPointData()->SetVectors(v);
  return test::writeRawVti(image, path);
}

template <class Reader>
vtkSmartPointer<vtkImageData> read(const std::filesystem::path& path) {
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

// Ours as the application reads: given the raw arrays checkVtkXml found.
struct OursRead {
  vtkSmartPointer<vtkImageData> image;
  std::size_t rawArrays = 0;
  std::size_t copied = 0;
};

OursRead readChecked(const std::filesystem::path& path) {
  VtkXmlSummary checked = checkVtkXml(path, std::size_t{1} << 32);
  vtkNew<HugePageImageReader> reader;
  reader->SetFileName(path.c_str());
  OursRead r;
  r.rawArrays = checked.raw.size();
  reader->setRawArrays(std::move(checked.raw));
  reader->Update();
  r.image = reader->GetOutput();
  r.copied = reader->arraysCopied();
  return r;
}

// Every point array of `a` has its namesake in `b`, with the same bytes.
void expectSameArrays(vtkImageData* a, vtkImageData* b) {
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->GetPointData()->GetNumberOfArrays(), b->GetPointData()->GetNumberOfArrays());
  for (int i = 0; i < a->GetPointData()->GetNumberOfArrays(); ++i) {
    vtkDataArray* x = a->GetPointData()->GetArray(i);
    vtkDataArray* y = b->GetPointData()->GetArray(x->GetName());
    ASSERT_TRUE(y) << x->GetName();
    ASSERT_EQ(x->GetDataType(), y->GetDataType());
    ASSERT_EQ(x->GetNumberOfValues(), y->GetNumberOfValues()) << x->GetName();
    const std::size_t bytes = std::size_t(x->GetNumberOfValues()) * x->GetDataTypeSize();
    EXPECT_EQ(std::memcmp(x->GetVoidPointer(0), y->GetVoidPointer(0), bytes), 0) << x->GetName();
  }
}

// A 150^3 field of vectors (40.5 MB) and of one double each (27 MB: VTK reads it).
vtkSmartPointer<vtkImageData> twoArrays() {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(kSide, kSide, kSide);
  const vtkIdType n = vtkIdType(kSide) * kSide * kSide;
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
    v->SetTuple3(i, double(i % 89) - 40.0, double(i % 7) * 0.5, double(i) * 1e-6);
  image->GetPointData()->SetVectors(v);
  vtkNew<vtkDoubleArray> t;
  t->SetName("temperature");
  t->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
    t->SetValue(i, 300.0 + double(i % 1000) * 1e-3);
  image->GetPointData()->AddArray(t);
  return image;
}

// The value of smaps' `key` for the mapping that holds `address`, or "" if none.
std::string smapsField(const void* address, const std::string& key) {
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= at && at < end;
      continue;
    }
    if (inside && line.rfind(key + ":", 0) == 0) return line.substr(key.size() + 1);
  }
  return "";
}

std::string thpSetting() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string s;
  std::getline(in, s);
  return s;
}

TEST(HugePageReader, ReadsWhatVtksReaderReads) {
  const auto path = writeImage(test::scratch() / "field.vti");
  const auto ours = read<HugePageImageReader>(path);
  const auto vtks = read<vtkXMLImageDataReader>(path);
  auto* a = vtkFloatArray::SafeDownCast(ours->GetPointData()->GetArray("velocity"));
  auto* b = vtkFloatArray::SafeDownCast(vtks->GetPointData()->GetArray("velocity"));
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->GetNumberOfValues(), vtkIdType(3) * kSide * kSide * kSide);
  ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues());
  EXPECT_EQ(std::memcmp(a->GetPointer(0), b->GetPointer(0), sizeof(float) * a->GetNumberOfValues()),
            0);
  int dims[3];
  ours->GetDimensions(dims);
  EXPECT_EQ(dims[0], kSide);
  EXPECT_EQ(dims[2], kSide);
}

TEST(HugePageReader, RawArraysCopiedOverTheCoresHoldWhatVtkReads) {
  // Both header widths; the vectors (past 32 MiB) are copied, the doubles
  // (below it) read by VTK, in the same file.
  for (const bool wide : {false, true}) {
    SCOPED_TRACE(wide ? "UInt64 headers" : "UInt32 headers");
    const auto image = twoArrays();
    const auto path = test::writeRawVti(image, test::scratch() / "two-arrays.vti", wide);
    const OursRead ours = readChecked(path);
    EXPECT_EQ(ours.rawArrays, 2u);
    EXPECT_EQ(ours.copied, 1u) << "the vectors copied, the 27 MB of doubles left to VTK";
    expectSameArrays(ours.image, read<vtkXMLImageDataReader>(path));
    expectSameArrays(ours.image, image);
  }
}

TEST(HugePageReader, ArraysStoredOtherwiseAreVtksToRead) {
  // base64 and compressed: nothing lies in the file as in memory.
  const auto image = twoArrays();
  for (const bool compressed : {false, true}) {
    SCOPED_TRACE(compressed ? "raw, compressed" : "base64");
    const auto path = test::scratch() / "encoded.vti";
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(image);
    w->SetFileName(path.c_str());
    w->SetDataModeToAppended();
    w->SetEncodeAppendedData(!compressed);
    if (compressed)
      w->SetCompressorTypeToZLib();
    else
      w->SetCompressorTypeToNone();
    ASSERT_EQ(w->Write(), 1);
    const OursRead ours = readChecked(path);
    EXPECT_EQ(ours.rawArrays, 0u);
    EXPECT_EQ(ours.copied, 0u);
    expectSameArrays(ours.image, image);
  }
}

TEST(HugePageReader, ASmallArrayIsLeftAlone) {
  // Below 32 MiB an array may lie on the heap, which outlives it: no advice.
  const std::string setting = thpSetting();
  if (setting.find("[madvise]") == std::string::npos)
    GTEST_SKIP() << "only a kernel that gives huge pages where asked tells (" << setting << ")";
  const auto path = test::scratch() / "small.vti";
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(96, 96, 96);  // 10.6 MB
    vtkNew<vtkFloatArray> v;
    v->SetName("velocity");
    v->SetNumberOfComponents(3);
    v->SetNumberOfTuples(96 * 96 * 96);
    v->Fill(0.5);
    image->GetPointData()->SetVectors(v);
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(image);
    w->SetFileName(path.c_str());
    w->Write();
  }
  const auto ours = read<HugePageImageReader>(path);
  auto* a = vtkFloatArray::SafeDownCast(ours->GetPointData()->GetArray("velocity"));
  ASSERT_TRUE(a);
  const std::string eligible = smapsField(a->GetPointer(a->GetNumberOfValues() / 2), "THPeligible");
  EXPECT_NE(eligible.find('0'), std::string::npos) << "THPeligible:" << eligible;
}

TEST(HugePageReader, TheArraysMemoryIsAdvisedForHugePages) {
  const std::string setting = thpSetting();
  if (setting.empty() || setting.find("[never]") != std::string::npos)
    GTEST_SKIP() << "this kernel gives no transparent huge pages (" << setting << ")";
  const auto path = writeImage(test::scratch() / "field.vti");
  const auto ours = read<HugePageImageReader>(path);
  auto* a = vtkFloatArray::SafeDownCast(ours->GetPointData()->GetArray("velocity"));
  ASSERT_TRUE(a);
  // A point inside the array's whole 2 MiB pages: the middle of the array.
  const float* middle = a->GetPointer(a->GetNumberOfValues() / 2);
  const std::string eligible = smapsField(middle, "THPeligible");
  ASSERT_FALSE(eligible.empty()) << "no smaps entry for the array";
  EXPECT_NE(eligible.find('1'), std::string::npos) << "THPeligible:" << eligible;
  if (setting.find("[madvise]") != std::string::npos) {
    // VTK's own reader leaves its array to the kernel's default: no huge pages.
    const auto vtks = read<vtkXMLImageDataReader>(path);
    auto* b = vtkFloatArray::SafeDownCast(vtks->GetPointData()->GetArray("velocity"));
    const std::string plain = smapsField(b->GetPointer(b->GetNumberOfValues() / 2), "THPeligible");
    EXPECT_NE(plain.find('0'), std::string::npos) << "THPeligible:" << plain;
  }
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// A file cut between its check and its read (a run still writing it, a
// network file system): the copy over the cores finds its end early and
// VTK's error names the file and the bytes missing; no crash, no hang, no
// image claimed whole.
TEST(HugePageReader, AFileCutAfterItsCheckIsAnErrorNamingIt) {
  const auto path = writeImage(test::scratch() / "cut.vti");
  VtkXmlSummary checked = checkVtkXml(path, std::size_t{1} << 32);
  ASSERT_EQ(checked.raw.size(), 1u);
  std::filesystem::resize_file(path, checked.raw.front().dataAt + checked.raw.front().bytes / 2);
  VtkMessageTrap trap(path);
  vtkNew<HugePageImageReader> reader;
  trap.watch(reader);
  reader->SetFileName(path.c_str());
  reader->setRawArrays(std::move(checked.raw));
  reader->Update();
  ASSERT_TRUE(trap.failed());
  const std::string all = [&] {
    std::string s;
    for (const std::string& e : trap.errors())
      s += e + "\n";
    return s;
  }();
  EXPECT_NE(all.find(path.string()), std::string::npos) << all;
  EXPECT_NE(all.find("the file ends before them"), std::string::npos) << all;
  EXPECT_EQ(reader->arraysCopied(), 0u);
  test::expectError([&] { trap.throwIfFailed("reading the image"); }, {path.string()});
}

}  // namespace
}  // namespace sandstorm
