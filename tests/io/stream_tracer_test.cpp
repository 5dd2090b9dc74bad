// Particles advected through a loaded field follow VTK's own vtkStreamTracer
// on the same file.
//
// vtkStreamTracer integrates the normalised field, dx/ds = v / |v|, in arc
// length s (with LENGTH_UNIT steps), while Sandstorm's tracers integrate
// dx/dt = v in time. Both trace the same curves, so the comparison is made at
// matching arc length: for every point VTK outputs, the point of our
// trajectory with the same arc length from the seed. Both interpolate the
// grid trilinearly and use RK4 with small fixed steps (VTK 0.01 m, ours
// 0.002 s, about 0.01 m at the field's speeds), so what remains is float
// rounding and the steps' truncation error.
#include <gtest/gtest.h>

#include <cstdio>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStreamTracer.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataReader.h>

#include "core/field/vortex_field.h"
#include "core/flow/streamline_tracer.h"
#include "core/flow/streamline_vtp.h"
#include "core/io/field_loader.h"
#include "core/sim/particle_physics.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

struct Path {
  std::vector<glm::dvec3> points;
  std::vector<double> arc;  // cumulative length
};

void appendPoint(Path& p, const glm::dvec3& x) {
  p.arc.push_back(p.points.empty() ? 0.0 : p.arc.back() + glm::length(x - p.points.back()));
  p.points.push_back(x);
}

glm::dvec3 atArc(const Path& p, double s) {
  auto it = std::lower_bound(p.arc.begin(), p.arc.end(), s);
  if (it == p.arc.begin()) return p.points.front();
  if (it == p.arc.end()) return p.points.back();
  const std::size_t b = std::size_t(it - p.arc.begin()), a = b - 1;
  const double w = (s - p.arc[a]) / (p.arc[b] - p.arc[a]);
  return p.points[a] + w * (p.points[b] - p.points[a]);
}

// The tornado of the thesis on a 41 x 41 x 33 grid, written by VTK's own writer.
void writeTornado(const std::filesystem::path& path) {
  const VortexField vortex(VortexParams{});
  vtkNew<vtkImageData> image;
  image->SetDimensions(41, 41, 33);
  image->SetOrigin(-5.0, -5.0, 0.0);
  image->SetSpacing(0.25, 0.25, 0.25);
  vtkNew<vtkDoubleArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i) {
    double x[3];
    image->GetPoint(i, x);
    const glm::vec3 f = vortex.evaluate(glm::vec3(x[0], x[1], x[2]));
    v->SetTuple3(i, f.x, f.y, f.z);
  }
  image->GetPointData()->SetVectors(v);
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1);
}

// VTK's RK4 tracer on the file from `seeds`, LENGTH_UNIT steps of 0.01 m,
// `propagation` metres at most, forward only or both ways.
vtkSmartPointer<vtkPolyData> vtkTrace(const std::filesystem::path& path,
                                      const std::vector<glm::dvec3>& seeds, double propagation,
                                      bool bothWays) {
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<vtkPolyData> seedData;
  vtkNew<vtkPoints> seedPoints;
  for (const auto& s : seeds)
    seedPoints->InsertNextPoint(s.x, s.y, s.z);
  seedData->SetPoints(seedPoints);
  vtkNew<vtkStreamTracer> tracer;
  tracer->SetInputConnection(reader->GetOutputPort());
  tracer->SetSourceData(seedData);
  tracer->SetIntegratorTypeToRungeKutta4();
  tracer->SetIntegrationStepUnit(vtkStreamTracer::LENGTH_UNIT);
  tracer->SetInitialIntegrationStep(0.01);
  tracer->SetMaximumPropagation(propagation);
  tracer->SetMaximumNumberOfSteps(100000);
  if (bothWays)
    tracer->SetIntegrationDirectionToBoth();
  else
    tracer->SetIntegrationDirectionToForward();
  tracer->SetTerminalSpeed(1e-9);
  tracer->SetComputeVorticity(false);
  tracer->Update();
  return tracer->GetOutput();
}

TEST(StreamTracer, Rk4TrajectoriesMatchVtkStreamTracer) {
  const auto dir = test::scratch();
  const auto path = dir / "tornado.vti";
  writeTornado(path);
  const std::vector<glm::dvec3> seeds{
      {1.5, 0.0, 1.0}, {0.0, 2.5, 2.0}, {-2.0, -1.0, 0.5}, {1.0, 1.0, 3.0}, {-0.3, 0.4, 1.2}};
  // VTK's tracer on the file.
  const vtkSmartPointer<vtkPolyData> traced = vtkTrace(path, seeds, 6.0, false);
  vtkPolyData* lines = traced;
  ASSERT_EQ(lines->GetNumberOfLines(), vtkIdType(seeds.size()));
  vtkDataArray* times = lines->GetPointData()->GetArray("IntegrationTime");
  ASSERT_NE(times, nullptr);

  // Ours through the loaded field.
  const VectorField field = loadField(path);
  PhysicsInputs in;
  in.field = &field;
  in.settings.motion = MotionModel::Tracer;
  in.settings.integrator = Integrator::RK4;
  in.settings.boundary = BoundaryMode::Kill;
  in.settings.groundCollision = false;
  in.dt = 0.002f;

  double worst = 0.0, worstTime = 0.0;
  vtkNew<vtkIdList> ids;
  lines->GetLines()->InitTraversal();
  while (lines->GetLines()->GetNextCell(ids)) {
    Path theirs;
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i) {
      double x[3];
      lines->GetPoint(ids->GetId(i), x);
      appendPoint(theirs, {x[0], x[1], x[2]});
    }
    ASSERT_GT(theirs.arc.back(), 2.0);  // a real trajectory, not a stagnant seed
    Path ours;
    std::vector<double> ourTimes;
    Particle p{glm::vec4(glm::vec3(theirs.points.front()), 1e6f), glm::vec4(0.0f, 0, 0, 1e6f)};
    appendPoint(ours, glm::dvec3(p.position()));
    ourTimes.push_back(0.0);
    while (ours.arc.back() < theirs.arc.back() + 0.05 && ourTimes.size() < 200000) {
      ASSERT_TRUE(advance(p, in)) << "left the field";
      appendPoint(ours, glm::dvec3(p.position()));
      ourTimes.push_back(ourTimes.back() + in.dt);
    }
    for (std::size_t i = 0; i < theirs.points.size(); ++i) {
      const double d = glm::length(atArc(ours, theirs.arc[i]) - theirs.points[i]);
      worst = std::max(worst, d);
    }
    // The time VTK reports for the end point against ours at that arc length.
    const double vtkTime = times->GetTuple1(ids->GetId(ids->GetNumberOfIds() - 1));
    const auto end = std::lower_bound(ours.arc.begin(), ours.arc.end(), theirs.arc.back());
    const double ourTime = ourTimes[std::size_t(end - ours.arc.begin())];
    worstTime = std::max(worstTime, std::abs(vtkTime - ourTime) / vtkTime);
  }
  std::printf(
      "[ measured ] max distance to vtkStreamTracer at equal arc length: %.3g m over 6 m "
      "paths (grid spacing 0.25 m); end-time difference %.3g%%\n",
      worst, 100.0 * worstTime);
  RecordProperty("max_distance_m", std::to_string(worst));
  EXPECT_LT(worst, 2e-3);      // 2 mm over 6 m, under 1% of a grid cell
  EXPECT_LT(worstTime, 5e-3);  // VTK's integration time within 0.5%
}

// Streamlines of the rake both ways against vtkStreamTracer's (BOTH
// directions, LENGTH_UNIT steps of 0.01 m, RK4): both integrate the normalised
// field in arc length, so they are compared at equal arc length from the seed.
TEST(StreamTracer, StreamlinesMatchVtkStreamTracerBothWays) {
  const auto dir = test::scratch();
  const auto path = dir / "tornado.vti";
  writeTornado(path);
  StreamlineSettings rake;
  rake.from = {-2.0f, 0.5f, 1.0f};
  rake.to = {2.0f, 0.5f, 3.0f};
  rake.seeds = 5;
  rake.step = 0.01f;
  rake.length = 4.0f;

  std::vector<glm::dvec3> seeds;
  for (const glm::vec3& s : rakeSeeds(rake))
    seeds.emplace_back(s);
  const vtkSmartPointer<vtkPolyData> traced = vtkTrace(path, seeds, 4.0, true);
  vtkPolyData* lines = traced;
  vtkDataArray* times = lines->GetPointData()->GetArray("IntegrationTime");
  ASSERT_NE(times, nullptr);

  const VectorField field = loadField(path);
  PhysicsInputs in;
  in.field = &field;
  in.settings.integrator = Integrator::RK4;
  const std::vector<Streamline> ours = traceStreamlines(rake, in);
  ASSERT_EQ(ours.size(), 5u);

  double worst = 0.0;
  int compared = 0;
  vtkNew<vtkIdList> ids;
  lines->GetLines()->InitTraversal();
  while (lines->GetLines()->GetNextCell(ids)) {
    if (ids->GetNumberOfIds() < 10) continue;
    Path theirs;
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i) {
      double x[3];
      lines->GetPoint(ids->GetId(i), x);
      appendPoint(theirs, {x[0], x[1], x[2]});
    }
    const bool backward = times->GetTuple1(ids->GetId(ids->GetNumberOfIds() - 1)) < 0.0;
    // Our line of the same seed, from the seed the same way.
    const Streamline* line = nullptr;
    for (const Streamline& l : ours)
      if (glm::length(glm::dvec3(l.points[std::size_t(l.seedIndex)].position) - theirs.points[0]) <
          1e-5)
        line = &l;
    ASSERT_NE(line, nullptr) << "no streamline of ours from the seed of VTK's";
    Path mine;
    const int n = int(line->points.size());
    for (int i = line->seedIndex; i >= 0 && i < n; i += backward ? -1 : 1)
      appendPoint(mine, glm::dvec3(line->points[std::size_t(i)].position));
    EXPECT_NEAR(mine.arc.back(), theirs.arc.back(), 0.02) << "both stop at 4 m or the field's edge";
    for (std::size_t i = 0; i < theirs.points.size(); ++i)
      if (theirs.arc[i] <= mine.arc.back())
        worst = std::max(worst, glm::length(atArc(mine, theirs.arc[i]) - theirs.points[i]));
    ++compared;
  }
  // Exported, the same lines read back in VTK point for point, with their arrays.
  const auto vtp = dir / "streamlines.vtp";
  writeStreamlinesVtp(ours, ColorQuantity::VelocityZ, vtp);
  vtkNew<vtkXMLPolyDataReader> back;
  back->SetFileName(vtp.c_str());
  back->Update();
  vtkPolyData* read = back->GetOutput();
  ASSERT_EQ(read->GetNumberOfLines(), vtkIdType(ours.size()));
  std::size_t total = 0;
  for (const Streamline& l : ours)
    total += l.points.size();
  ASSERT_EQ(read->GetNumberOfPoints(), vtkIdType(total));
  for (const char* name : {"velocity", "speed", "arc_length", "velocity_z"})
    ASSERT_NE(read->GetPointData()->GetArray(name), nullptr) << name;
  read->GetLines()->InitTraversal();
  for (const Streamline& l : ours) {
    ASSERT_TRUE(read->GetLines()->GetNextCell(ids));
    ASSERT_EQ(ids->GetNumberOfIds(), vtkIdType(l.points.size()));
    for (std::size_t i = 0; i < l.points.size(); i += 37) {
      double x[3];
      read->GetPoint(ids->GetId(vtkIdType(i)), x);
      EXPECT_FLOAT_EQ(float(x[0]), l.points[i].position.x);
      EXPECT_FLOAT_EQ(float(x[2]), l.points[i].position.z);
      EXPECT_FLOAT_EQ(
          float(read->GetPointData()->GetArray("velocity_z")->GetTuple1(ids->GetId(vtkIdType(i)))),
          l.points[i].velocity.z);
    }
    EXPECT_FLOAT_EQ(float(read->GetPointData()
                              ->GetArray("arc_length")
                              ->GetTuple1(ids->GetId(vtkIdType(l.seedIndex)))),
                    0.0f);
  }
  std::printf(
      "[ measured ] streamlines vs vtkStreamTracer, %d directions of up to 4 m: max %.3g m\n",
      compared, worst);
  EXPECT_GE(compared, 8);
  EXPECT_LT(worst, 2e-3);
}

}  // namespace
}  // namespace sandstorm
