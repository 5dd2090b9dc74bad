// field.precision = "half" on a .vti: the reader rounds each float to the
// nearest half in the pass that checks it (vtk_field_extractor), instead of
// VectorField::roundToHalf's two passes after it. The result must be what
// roundToHalf makes of the same file read in floats, bit for bit, over a grid
// of many blocks with non-finite vectors and masked points in some of them,
// and a component beyond a half's range must be refused as roundToHalf does.
#include <bit>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataWriter.h>

#include "core/io/field_loader.h"
#include "core/util/error.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

constexpr int kNx = 41, kNy = 37, kNz = 23;  // 34 891 points: blocks of 2048 and a partial one

// Values that are not halves (thirds, tiny and large ones), a NaN and an
// infinity, `big` at one point, and (when `masked`) a validity mask hiding
// one slab.
std::filesystem::path writeImage(const std::filesystem::path& path, bool masked, float big = 0.0f) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(kNx, kNy, kNz);
  image->SetSpacing(0.25, 0.5, 1.0);
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> valid;
  valid->SetName("vtkValidPointMask");
  int n = 0;
  for (int k = 0; k < kNz; ++k)
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i, ++n) {
        float x = float(i) / 3.0f - 7.0f, y = 1e-6f * float(j * j) + 0.1f, z = 2900.7f * float(k);
        if (n == 5000) x = std::numeric_limits<float>::quiet_NaN();
        if (n == 30001) z = -std::numeric_limits<float>::infinity();
        if (n == 20000 && big != 0.0f) y = big;
        v->InsertNextTuple3(x, y, z);
        valid->InsertNextValue(j >= 10 && j < 12 ? 0 : 1);
      }
  image->GetPointData()->SetVectors(v);
  if (masked) image->GetPointData()->AddArray(valid);
  return test::writeRawVti(image, path);
}

TEST(VtiHalf, RoundingWhileReadingEqualsRoundingAfter) {
  const auto dir = test::scratch();
  for (const bool masked : {false, true}) {
    SCOPED_TRACE(masked ? "masked" : "plain");
    const auto path = writeImage(dir / "field.vti", masked);
    LoadOptions halves;
    halves.halfPrecision = true;
    const VectorField read = loadField(path, halves);
    VectorField rounded = loadField(path);
    ASSERT_FALSE(rounded.halfPrecision());
    rounded.roundToHalf();
    const VectorField& after = rounded;  // read only: writing access forgets the range
    EXPECT_TRUE(read.halfPrecision());
    ASSERT_EQ(read.values().size(), after.values().size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < read.values().size(); ++i)
      for (int c = 0; c < 3; ++c)
        differ += std::bit_cast<std::uint32_t>(read.values()[i][c]) !=
                  std::bit_cast<std::uint32_t>(after.values()[i][c]);
    EXPECT_EQ(differ, 0u);
    // Rounded indeed: 1/3 - 7 is no half, and the NaN and infinity are zero.
    EXPECT_NE(read.values()[1].x, 1.0f / 3.0f - 7.0f);
    EXPECT_EQ(read.values()[5000].x, 0.0f);
    EXPECT_EQ(read.values()[30001].z, 0.0f);
    ASSERT_TRUE(read.rememberedRange());
    ASSERT_TRUE(after.rememberedRange());
    EXPECT_EQ(*read.rememberedRange(), *after.rememberedRange());
  }
}

TEST(VtiHalf, AComponentBeyondAHalfIsRefusedAsRoundToHalfRefusesIt) {
  const auto dir = test::scratch();
  const auto path = writeImage(dir / "big.vti", false, 70000.0f);
  LoadOptions halves;
  halves.halfPrecision = true;
  std::string whileReading, after;
  try {
    loadField(path, halves);
  } catch (const Error& e) {
    whileReading = e.what();
  }
  VectorField f = loadField(path);
  try {
    f.roundToHalf();
  } catch (const Error& e) {
    after = e.what();
  }
  EXPECT_NE(whileReading.find("point 20000 has the component 70000"), std::string::npos)
      << whileReading;
  EXPECT_NE(whileReading.find("field.precision"), std::string::npos);
  EXPECT_NE(whileReading.find(path.string()), std::string::npos) << whileReading;
  EXPECT_NE(after.find("point 20000 has the component 70000"), std::string::npos) << after;
  EXPECT_FALSE(f.halfPrecision());
}

}  // namespace
}  // namespace sandstorm
