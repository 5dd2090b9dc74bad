// A .vti's reader finds the field's speed and velocity range while it checks
// each vector (VectorField::rememberRange), so that the main context does not
// read a series' step once more: that range must be the one found from the
// values afterwards, over the valid points, with non-finite vectors zeroed,
// and with half precision the rounded values' range.
#include <cmath>
#include <limits>

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataWriter.h>

#include "core/field/field_range.h"
#include "core/io/field_loader.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

// 6x5x4 points of v = (i - 2.5, j * 0.3, -k), one NaN and one infinite
// vector, and (when `masked`) a vtkValidPointMask hiding the last layer (k = 3).
std::filesystem::path writeImage(const std::filesystem::path& dir, bool masked) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(6, 5, 4);
  image->SetSpacing(0.5, 0.5, 0.5);
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> valid;
  valid->SetName("vtkValidPointMask");
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 6; ++i) {
        float x = float(i) - 2.5f;
        if (i == 1 && j == 1 && k == 1) x = std::numeric_limits<float>::quiet_NaN();
        if (i == 2 && j == 3 && k == 0) x = std::numeric_limits<float>::infinity();
        v->InsertNextTuple3(x, j * 0.3f + 0.01f, -float(k));
        valid->InsertNextValue(k == 3 ? 0 : 1);
      }
  image->GetPointData()->SetVectors(v);
  if (masked) image->GetPointData()->AddArray(valid);
  const auto path = dir / (masked ? "masked.vti" : "plain.vti");
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(image);
  w->SetFileName(path.c_str());
  w->Write();
  return path;
}

// The range found again from the values: setValidity forgets the reader's.
FieldRange foundAgain(const VectorField& field, const glm::mat3& rotation = glm::mat3(1.0f)) {
  VectorField copy = field;
  copy.setValidity(std::vector<std::uint8_t>(field.validity().begin(), field.validity().end()));
  EXPECT_FALSE(copy.rememberedRange());
  return FieldRange::of(copy, rotation);
}

TEST(RememberedRange, TheReadersRangeIsTheValuesOwn) {
  const auto dir = test::scratch();
  for (const bool masked : {false, true}) {
    for (const bool half : {false, true}) {
      SCOPED_TRACE(masked ? "masked" : "plain");
      SCOPED_TRACE(half ? "half" : "float");
      LoadOptions options;
      options.halfPrecision = half;
      const VectorField f = loadField(writeImage(dir, masked), options);
      ASSERT_TRUE(f.rememberedRange());
      const FieldRange r = FieldRange::of(f);
      EXPECT_EQ(r, foundAgain(f));
      // The fastest vector, over every point (masked ones are zeroed), alike.
      VectorField forgotten = f;
      forgotten.values();
      EXPECT_FALSE(forgotten.rememberedRange());
      EXPECT_EQ(f.maxMagnitude(), forgotten.maxMagnitude());
      EXPECT_EQ(f.maxMagnitude(), r.maxSpeed);
      // The non-finite vectors are zeroed, so the slowest speed is 0; the
      // fastest are the corners (+-2.5, 1.21, -3), or (+-2.5, 1.21, -2) when masked.
      EXPECT_EQ(r.minSpeed, 0.0f);
      const float fastest = std::sqrt(2.5f * 2.5f + 1.21f * 1.21f + (masked ? 4.0f : 9.0f));
      EXPECT_NEAR(r.maxSpeed, fastest, half ? 2e-3f : 1e-6f);
      EXPECT_EQ(r.minVelocity.z, masked ? -2.0f : -3.0f);
      // Turned into the particles' axes, the range is found from the values.
      const glm::mat3 turn(0, 1, 0, -1, 0, 0, 0, 0, 1);
      EXPECT_EQ(FieldRange::of(f, turn), foundAgain(f, turn));
      EXPECT_NEAR(FieldRange::of(f, turn).minVelocity.x, -1.21f, 1e-3f);
    }
  }
}

}  // namespace
}  // namespace sandstorm
