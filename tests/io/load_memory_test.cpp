// A grid read from a file is held once: loading it raises this process's
// resident memory by about the grid's size, not twice it (VTK's array and a
// copy, as it did: 2.0x measured before). Measured as the peak resident set
// (VmHWM, reset first through /proc/self/clear_refs) over the resident set
// before the load. Every format read through a path of its own is here: a
// .vti, a .pvti of one piece and of eight, a legacy .vtk.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <string>

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include "core/io/field_loader.h"
#include "core/io/vti_writer.h"
#include "tests/io/index_files.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

namespace fs = std::filesystem;

// A line of /proc/self/status ("VmRSS", "VmHWM") in KiB.
std::optional<long> statusKiB(const std::string& key) {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.starts_with(key + ":")) return std::stol(line.substr(key.size() + 1));
  return std::nullopt;
}

// Sets the peak resident set to the current one; false where Linux does not allow it.
bool resetPeak() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return bool(out);
}

VectorField swirl(int side) {
  VectorField f(Box{{-1, -1, -1}, {1, 1, 1}}, glm::ivec3(side));
  for (int k = 0; k < side; ++k)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        const glm::vec3 p = f.pointPosition(i, j, k);
        f.at(i, j, k) = {-p.y, p.x, std::sin(3.0f * p.z)};
      }
  return f;
}

// AddressSanitizer keeps freed memory in quarantine: not the memory users see.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
constexpr bool kSanitized = __has_feature(address_sanitizer);
#else
constexpr bool kSanitized = false;
#endif

// The image frame of `field`'s grid.
VtkImageFrame frameOf(const VectorField& field) {
  VtkImageFrame frame;
  const glm::ivec3 d = field.dims();
  frame.extent = {0, d.x - 1, 0, d.y - 1, 0, d.z - 1};
  for (int a = 0; a < 3; ++a) {
    frame.origin[std::size_t(a)] = field.bounds().min[a];
    frame.spacing[std::size_t(a)] =
        double(field.bounds().max[a] - field.bounds().min[a]) / double(d[a] - 1);
  }
  return frame;
}

// Layers z0..z1 of `whole` as an image of `frame` with the array "velocity".
vtkSmartPointer<vtkImageData> slab(const VectorField& whole, const VtkImageFrame& frame, int z0,
                                   int z1) {
  const glm::ivec3 d = whole.dims();
  auto im = vtkSmartPointer<vtkImageData>::New();
  im->SetExtent(0, d.x - 1, 0, d.y - 1, z0, z1);
  im->SetOrigin(frame.origin.data());
  im->SetSpacing(frame.spacing.data());
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(im->GetNumberOfPoints());
  vtkIdType n = 0;
  for (int k = z0; k <= z1; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i, ++n) {
        const glm::vec3 w = whole.at(i, j, k);
        v->SetTuple3(n, w.x, w.y, w.z);
      }
  im->GetPointData()->AddArray(v);
  return im;
}

TEST(LoadMemory, AGridIsHeldOnceNotCopied) {
  if (kSanitized) GTEST_SKIP() << "a sanitized build measures the sanitizer's memory";
  const fs::path dir = test::scratch();
  constexpr int kSide = 192;  // 85 MB of vectors
  const glm::vec3 probe = swirl(kSide).at(5, 7, 11);
  for (const VtiCompression c : {VtiCompression::None, VtiCompression::ZLib}) {
    writeVti(dir / "big.vti", swirl(kSide), "velocity", c);
    if (!resetPeak()) GTEST_SKIP() << "/proc/self/clear_refs cannot be written here";
    const std::optional<long> before = statusKiB("VmRSS");
    LoadOptions options;
    const VectorField read = loadField(dir / "big.vti", options);
    const std::optional<long> peak = statusKiB("VmHWM");
    ASSERT_TRUE(before && peak);
    const double gridKiB = double(read.pointCount()) * 12.0 / 1024.0;
    // The grid, and a fifth of it for what reading it takes besides.
    EXPECT_LT(double(*peak - *before), 1.2 * gridKiB)
        << (c == VtiCompression::None ? "uncompressed" : "zlib") << ": peak " << *peak
        << " KiB over " << *before << " KiB before the load; the grid is " << gridKiB << " KiB";
    // The reader keeps VTK's array as the grid's values.
    EXPECT_TRUE(read.adoptedValues());
    EXPECT_EQ(read.at(5, 7, 11), probe);
  }
}

// Loads `file` (the peak reset just before) and expects the resident
// memory the load added at its peak below `limit` times the grid's bytes.
VectorField loadWithin(const fs::path& file, double limit) {
  const std::optional<long> before = statusKiB("VmRSS");
  VectorField read = loadField(file, LoadOptions{});
  const std::optional<long> peak = statusKiB("VmHWM");
  EXPECT_TRUE(before && peak);
  const double gridKiB = double(read.pointCount()) * 12.0 / 1024.0;
  if (before && peak)
    EXPECT_LT(double(*peak - *before), limit* gridKiB)
        << file.filename() << ": peak " << *peak << " KiB over " << *before
        << " KiB before the load; the grid is " << gridKiB << " KiB";
  return read;
}

// The same grid as the one piece of a parallel image file (.pvti): the
// image takes the piece's array (ParallelImageReader) where VTK's own
// reader copied it into a second one (1.7x measured before).
TEST(LoadMemory, APieceThatIsTheWholeGridIsHeldOnce) {
  if (kSanitized) GTEST_SKIP() << "a sanitized build measures the sanitizer's memory";
  const fs::path dir = test::scratch();
  constexpr int kSide = 192;  // 85 MB of vectors
  const glm::vec3 probe = swirl(kSide).at(5, 7, 11);
  writeVti(dir / "big.vti", swirl(kSide), "velocity", VtiCompression::None);
  test::writePvtiFor(dir / "big.vti", dir / "big.pvti");
  if (!resetPeak()) GTEST_SKIP() << "/proc/self/clear_refs cannot be written here";
  const VectorField read = loadWithin(dir / "big.pvti", 1.2);
  EXPECT_TRUE(read.adoptedValues());
  EXPECT_EQ(read.at(5, 7, 11), probe);
}

// The grid as eight pieces (slabs along z, as eight ranks write it): each
// piece's array goes once its part is copied into the grid, so the peak is
// the grid and a piece, not the grid and every piece (VTK's reader: 2x).
TEST(LoadMemory, AGridInPiecesIsHeldOnceWithAPieceBeside) {
  if (kSanitized) GTEST_SKIP() << "a sanitized build measures the sanitizer's memory";
  const fs::path dir = test::scratch();
  constexpr int kSide = 192, kPieces = 8;
  const VectorField whole = swirl(kSide);
  const VtkImageFrame frame = frameOf(whole);
  std::vector<std::pair<std::array<long long, 6>, fs::path>> pieces;
  for (int p = 0; p < kPieces; ++p) {
    const int z0 = p * (kSide - 1) / kPieces, z1 = (p + 1) * (kSide - 1) / kPieces;
    const fs::path file = dir / ("piece" + std::to_string(p) + ".vti");
    test::writeRawVti(slab(whole, frame, z0, z1), file);
    pieces.push_back({{0, kSide - 1, 0, kSide - 1, z0, z1}, file});
  }
  test::writePvti(dir / "pieces.pvti", frame, pieces);
  if (!resetPeak()) GTEST_SKIP() << "/proc/self/clear_refs cannot be written here";
  // The grid, a piece (an eighth) and what reading takes besides.
  const VectorField read = loadWithin(dir / "pieces.pvti", 1.25);
  ASSERT_EQ(read.dims(), glm::ivec3(kSide));
  for (const glm::ivec3 at :
       {glm::ivec3(5, 7, 11), glm::ivec3(191, 0, 24), glm::ivec3(3, 190, 191)})
    EXPECT_EQ(read.at(at.x, at.y, at.z), whole.at(at.x, at.y, at.z));
}

// A legacy .vtk of BINARY floats (VTK's own writer): the parse gives the
// file's text back as it passes it, keeps the floats as float and hands them
// to VTK, which the grid adopts (3.2x the grid measured before: the text,
// the values as double and VTK's copy of them).
TEST(LoadMemory, ALegacyBinaryFileIsHeldAboutOnce) {
  if (kSanitized) GTEST_SKIP() << "a sanitized build measures the sanitizer's memory";
  const fs::path dir = test::scratch();
  constexpr int kSide = 192;  // 85 MB of vectors
  const VectorField whole = swirl(kSide);
  ASSERT_TRUE(test::writeStructuredPoints(slab(whole, frameOf(whole), 0, kSide - 1),
                                          dir / "big.vtk", true));
  if (!resetPeak()) GTEST_SKIP() << "/proc/self/clear_refs cannot be written here";
  // The grid, the few MiB of text not yet given back, and what reading takes besides.
  const VectorField read = loadWithin(dir / "big.vtk", 1.25);
  ASSERT_EQ(read.dims(), glm::ivec3(kSide));
  for (const glm::ivec3 at :
       {glm::ivec3(5, 7, 11), glm::ivec3(191, 0, 24), glm::ivec3(3, 190, 191)})
    EXPECT_EQ(read.at(at.x, at.y, at.z), whole.at(at.x, at.y, at.z));
}

}  // namespace
}  // namespace sandstorm
