// Helpers shared by the io tests: a scratch folder per test, the asymmetric
// reference field, and an Error matcher.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredPointsWriter.h>
#include <vtkXMLImageDataWriter.h>
#include <glm/glm.hpp>

#include "core/io/vtk_message_trap.h"
#include "core/util/error.h"

namespace sandstorm::test {

// v = (x, 2y, 3z) + (1, -2, 0.5): every component differs and is linear, so
// trilinear interpolation reproduces it exactly and any swapped or flipped
// axis shows.
inline glm::dvec3 asymmetric(const glm::dvec3& p) {
  return {p.x + 1.0, 2.0 * p.y - 2.0, 3.0 * p.z + 0.5};
}

// The asymmetric field at `data`'s points: a float point array "velocity".
inline void addAsymmetricVelocity(vtkDataSet* data) {
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double p[3];
    data->GetPoint(i, p);
    const glm::dvec3 a = asymmetric({p[0], p[1], p[2]});
    v->SetTuple3(i, a.x, a.y, a.z);
  }
  data->GetPointData()->AddArray(v);
}

// An image of the asymmetric field as float vectors "velocity" over
// `extent`, with `origin` and `spacing`.
inline vtkSmartPointer<vtkImageData> asymmetricImage(const int (&extent)[6], glm::dvec3 origin,
                                                     glm::dvec3 spacing) {
  auto im = vtkSmartPointer<vtkImageData>::New();
  im->SetExtent(extent[0], extent[1], extent[2], extent[3], extent[4], extent[5]);
  im->SetOrigin(origin.x, origin.y, origin.z);
  im->SetSpacing(spacing.x, spacing.y, spacing.z);
  addAsymmetricVelocity(im);
  im->GetPointData()->SetActiveVectors("velocity");
  return im;
}

// A fresh folder named after the running test.
inline std::filesystem::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(info->test_suite_name()) + "." + info->name();
  for (char& c : name)
    if (c == '/') c = '_';
  const auto dir = std::filesystem::temp_directory_path() / "sandstorm_io_tests" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  VtkMessageTrap::installOutputWindow();  // keeps VTK's own console output quiet
  return dir;
}

// `image` as a .vti of raw appended data, uncompressed (a series' step as
// sandstorm-field convert --compression none writes it); `wideHeaders`:
// UInt64 byte counts. A failed write fails the test. Returns `path`.
inline std::filesystem::path writeRawVti(vtkImageData* image, const std::filesystem::path& path,
                                         bool wideHeaders = false) {
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(image);
  w->SetFileName(path.c_str());
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();
  w->SetCompressorTypeToNone();
  if (wideHeaders) w->SetHeaderTypeToUInt64();
  EXPECT_EQ(w->Write(), 1) << "writing " << path;
  return path;
}

// `image` as a legacy .vtk of STRUCTURED_POINTS, ASCII or BINARY, by VTK's
// writer. Whether it was written.
inline bool writeStructuredPoints(vtkImageData* image, const std::filesystem::path& path,
                                  bool binary) {
  vtkNew<vtkStructuredPointsWriter> w;
  w->SetInputData(image);
  w->SetFileName(path.c_str());
  if (binary)
    w->SetFileTypeToBinary();
  else
    w->SetFileTypeToASCII();
  return w->Write() == 1;
}

inline void writeText(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

inline std::string readAll(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Expects f() to throw sandstorm::Error whose message holds every one of `parts`.
inline void expectError(const std::function<void()>& f, std::initializer_list<std::string> parts) {
  try {
    f();
    ADD_FAILURE() << "no Error thrown; expected one mentioning '" << *parts.begin() << "'";
  } catch (const Error& e) {
    const std::string what = e.what();
    for (const std::string& part : parts)
      EXPECT_NE(what.find(part), std::string::npos) << "'" << part << "' missing from: " << what;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw a non-Error exception: " << e.what();
  }
}

}  // namespace sandstorm::test
