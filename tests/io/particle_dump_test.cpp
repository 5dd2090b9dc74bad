// --dump-particles writes VTK PolyData; VTK's own reader (what ParaView uses)
// must read back every particle's position, velocity and age.
#include "core/sim/particle_dump.h"

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>

namespace sandstorm {
namespace {

TEST(ParticleDump, VtkReadsEveryParticleBack) {
  std::vector<Particle> particles;
  for (int i = 0; i < 257; ++i) {
    const float f = float(i);
    particles.push_back(Particle{glm::vec4(f, -2.0f * f, 0.5f + f, 3.0f - 0.01f * f),
                                 glm::vec4(0.1f * f, 1.0f, -f, 3.5f)});
  }
  const auto path = std::filesystem::temp_directory_path() / "sandstorm-dump.vtp";
  writeParticlesVtp(particles, path);

  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  ASSERT_EQ(poly->GetNumberOfPoints(), 257);
  EXPECT_EQ(poly->GetNumberOfVerts(), 257);  // one vertex cell each: ParaView shows them as points
  vtkDataArray* velocity = poly->GetPointData()->GetArray("velocity");
  vtkDataArray* age = poly->GetPointData()->GetArray("age");
  vtkDataArray* life = poly->GetPointData()->GetArray("life_remaining");
  ASSERT_TRUE(velocity && age && life);
  for (int i = 0; i < 257; i += 16) {
    double p[3], v[3];
    poly->GetPoint(i, p);
    velocity->GetTuple(i, v);
    EXPECT_FLOAT_EQ(float(p[1]), particles[std::size_t(i)].positionLife.y);
    EXPECT_FLOAT_EQ(float(v[2]), particles[std::size_t(i)].velocityKind.z);
    EXPECT_FLOAT_EQ(float(age->GetTuple1(i)), particles[std::size_t(i)].age());
    EXPECT_FLOAT_EQ(float(life->GetTuple1(i)), particles[std::size_t(i)].life());
  }
}

TEST(ParticleDump, NoParticlesIsStillAValidFile) {
  const auto path = std::filesystem::temp_directory_path() / "sandstorm-empty.vtp";
  writeParticlesVtp({}, path);
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}

}  // namespace
}  // namespace sandstorm
