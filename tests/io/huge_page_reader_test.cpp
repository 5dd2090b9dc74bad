// HugePageImageReader (core/io/huge_page_image_reader.h): VTK's .vti reader
// with its large point arrays advised for transparent huge pages. It must
// read exactly what vtkXMLImageDataReader reads, and the array's memory must
// carry the advice (the kernel's smaps says the region may take huge pages)
// wherever the kernel has them at all.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>

#include "core/io/huge_page_image_reader.h"
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
