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

#include <algorithm>
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

// VTK's tracer on the file from `seeds`, `propagation` metres at most,
// forward only or both ways: RK4 in LENGTH_UNIT steps of 0.01 m, or with
// `rk45`, adaptive RK45 with steps of 0.0001 .. 0.01 m and a maximum error
// of 1e-9: the reference a tolerance-driven integrator should reach.
vtkSmartPointer<vtkPolyData> vtkTrace(const std::filesystem::path& path,
                                      const std::vector<glm::dvec3>& seeds, double propagation,
                                      bool bothWays, bool rk45 = false) {
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
  tracer->SetIntegrationStepUnit(vtkStreamTracer::LENGTH_UNIT);
  tracer->SetInitialIntegrationStep(0.01);
  if (rk45) {
    tracer->SetIntegratorTypeToRungeKutta45();
    tracer->SetMinimumIntegrationStep(0.0001);
    tracer->SetMaximumIntegrationStep(0.01);
    tracer->SetMaximumError(1e-9);
  } else {
    tracer->SetIntegratorTypeToRungeKutta4();
  }
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

// VTK's streamlines (of at least 10 points) each beside ours from the same
// seed the same way, both as paths from the seed.
struct LinePair {
  Path theirs, mine;
};
std::vector<LinePair> pairWithOurs(vtkPolyData* lines, const std::vector<Streamline>& ours) {
  vtkDataArray* times = lines->GetPointData()->GetArray("IntegrationTime");
  std::vector<LinePair> pairs;
  if (!times) {
    ADD_FAILURE() << "VTK's lines have no IntegrationTime";
    return pairs;
  }
  vtkNew<vtkIdList> ids;
  lines->GetLines()->InitTraversal();
  while (lines->GetLines()->GetNextCell(ids)) {
    if (ids->GetNumberOfIds() < 10) continue;
    LinePair pair;
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i) {
      double x[3];
      lines->GetPoint(ids->GetId(i), x);
      appendPoint(pair.theirs, {x[0], x[1], x[2]});
    }
    const bool backward = times->GetTuple1(ids->GetId(ids->GetNumberOfIds() - 1)) < 0.0;
    const Streamline* line = nullptr;
    for (const Streamline& l : ours)
      if (glm::length(glm::dvec3(l.points[std::size_t(l.seedIndex)].position) -
                      pair.theirs.points[0]) < 1e-5)
        line = &l;
    if (!line) {
      ADD_FAILURE() << "no streamline of ours from the seed of VTK's";
      continue;
    }
    const int n = int(line->points.size());
    for (int i = line->seedIndex; i >= 0 && i < n; i += backward ? -1 : 1)
      appendPoint(pair.mine, glm::dvec3(line->points[std::size_t(i)].position));
    pairs.push_back(std::move(pair));
  }
  return pairs;
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
  rake.integrator = StreamIntegrator::RK4;

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
  const std::vector<Streamline> ours = traceStreamlines(rake, in);
  ASSERT_EQ(ours.size(), 5u);

  double worst = 0.0;
  int compared = 0;
  for (const auto& [theirs, mine] : pairWithOurs(lines, ours)) {
    EXPECT_NEAR(mine.arc.back(), theirs.arc.back(), 0.02) << "both stop at 4 m or the field's edge";
    for (std::size_t i = 0; i < theirs.points.size(); ++i)
      if (theirs.arc[i] <= mine.arc.back())
        worst = std::max(worst, glm::length(atArc(mine, theirs.arc[i]) - theirs.points[i]));
    ++compared;
  }
  // Exported, the same lines read back in VTK point for point, with their arrays.
  vtkNew<vtkIdList> ids;
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

// The distance from x to the polyline p (its nearest segment).
double toPolyline(const glm::dvec3& x, const Path& p) {
  double best = glm::length(x - p.points.front());
  for (std::size_t i = 1; i < p.points.size(); ++i) {
    const glm::dvec3 a = p.points[i - 1], d = p.points[i] - a;
    const double len2 = glm::dot(d, d);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(x - a, d) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, glm::length(x - (a + t * d)));
  }
  return best;
}

// The largest distance from our points to VTK's line from the same seed the
// same way (VTK's dense: its chords' sagitta is under 3e-5 m here), and
// whether both end alike; `compared` counts the directions.
double worstAgainst(vtkPolyData* lines, const std::vector<Streamline>& ours, double ends,
                    int& compared) {
  double worst = 0.0;
  compared = 0;
  for (const auto& [theirs, mine] : pairWithOurs(lines, ours)) {
    // Both stop at 5 m or at the field's edge (RK45 within a step's sixty-fourth).
    EXPECT_NEAR(mine.arc.back(), theirs.arc.back(), ends);
    // Points at the end of VTK's line or past it have nothing to be compared
    // with: the two measure 5 m by their own chords, which fall short of the
    // arc by different amounts (ours are longer), so ours ends a little ahead.
    for (std::size_t i = 0; i < mine.points.size(); ++i)
      if (mine.arc[i] <= theirs.arc.back() - 0.02)
        worst = std::max(worst, toPolyline(mine.points[i], theirs));
    ++compared;
  }
  return worst;
}

// At the defaults a user gets (streamlines.integrator = rk45, its tolerance
// and step), the streamlines are those of VTK's RK45 driven to a far tighter
// error: every point of ours within 1e-4 m of VTK's line over 5 m each way;
// the particles' integrator (here Euler) does not enter. Fixed RK2 at the
// same step is measured beside it.
TEST(StreamTracer, DefaultStreamlinesMatchVtkRk45WithinATenthOfAMillimetre) {
  const auto dir = test::scratch();
  const auto path = dir / "tornado.vti";
  writeTornado(path);
  StreamlineSettings rake;  // the defaults: rk45, step 0.05 m, tolerance 1e-6 m
  rake.from = {-2.0f, 0.5f, 1.0f};
  rake.to = {2.0f, 0.5f, 3.0f};
  rake.seeds = 5;
  rake.length = 5.0f;
  std::vector<glm::dvec3> seeds;
  for (const glm::vec3& s : rakeSeeds(rake))
    seeds.emplace_back(s);
  const vtkSmartPointer<vtkPolyData> traced = vtkTrace(path, seeds, 5.0, true, true);

  const VectorField field = loadField(path);
  PhysicsInputs in;
  in.field = &field;
  in.settings.integrator = Integrator::Euler;
  int compared = 0;
  const double worst = worstAgainst(traced, traceStreamlines(rake, in), 0.01, compared);
  StreamlineSettings rk2 = rake;
  rk2.integrator = StreamIntegrator::RK2;
  int compared2 = 0;
  const double worstRk2 =
      worstAgainst(traced, traceStreamlines(rk2, in), rk2.step + 0.01, compared2);
  std::printf(
      "[ measured ] default streamlines (rk45, step 0.05 m, tolerance 1e-6 m) vs vtkStreamTracer "
      "RK45 (max error 1e-9), %d directions of up to 5 m: max %.3g m; fixed rk2 at 0.05 m: "
      "%.3g m\n",
      compared, worst, worstRk2);
  EXPECT_GE(compared, 8);
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(worstRk2, worst);
}

}  // namespace
}  // namespace sandstorm
