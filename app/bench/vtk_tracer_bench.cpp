// sandstorm-vtk-bench: the peer of sandstorm-bench's particle update: VTK's
// vtkStreamTracer (RK4, fixed steps) through the benchmark's tornado, baked on
// the same 64x64x48 grid, from seeds on the same disc, on this machine's CPU.
// Reports RK4 particle-steps per second, and the same for Sandstorm's CPU
// reference simulator (RK4 tracers) for scale. The GPU's number comes from
//   sandstorm-bench --sections update --backends compute --integrator rk4
// (docs/PERFORMANCE.md sets the two side by side).
//
// Links VTK, which sandstorm-bench itself must not.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStreamTracer.h>

#include "core/field/vortex_field.h"
#include "core/sim/reference_simulator.h"

namespace {

using namespace sandstorm;

double seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const int seeds = argc > 1 ? std::atoi(argv[1]) : 2000;
  const int maxSteps = argc > 2 ? std::atoi(argv[2]) : 2000;
  VortexParams vp;
  vp.range = 5.0f;
  vp.height = 9.0f;
  const VortexField vortex(vp);
  const Box box{{-6.0f, -6.0f, 0.0f}, {6.0f, 6.0f, 10.0f}};
  const glm::ivec3 dims{64, 64, 48};
  auto field = std::make_shared<VectorField>(bake(vortex, box, dims));

  // The field as VTK image data (float vectors, as Sandstorm's grid).
  vtkNew<vtkImageData> image;
  image->SetDimensions(dims.x, dims.y, dims.z);
  image->SetOrigin(box.min.x, box.min.y, box.min.z);
  image->SetSpacing((box.max.x - box.min.x) / (dims.x - 1), (box.max.y - box.min.y) / (dims.y - 1),
                    (box.max.z - box.min.z) / (dims.z - 1));
  vtkNew<vtkFloatArray> vectors;
  vectors->SetName("velocity");
  vectors->SetNumberOfComponents(3);
  vectors->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i) {
    const glm::vec3 v = field->values()[std::size_t(i)];
    vectors->SetTuple3(i, v.x, v.y, v.z);
  }
  image->GetPointData()->SetVectors(vectors);

  // Seeds on the benchmark's emitter disc (radius 3.5 m at 0.5 m).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  vtkNew<vtkPoints> points;
  while (points->GetNumberOfPoints() < seeds) {
    const double x = u(rng), y = u(rng);
    if (x * x + y * y <= 1.0) points->InsertNextPoint(3.5 * x, 3.5 * y, 0.5);
  }
  vtkNew<vtkPolyData> seedData;
  seedData->SetPoints(points);

  vtkNew<vtkStreamTracer> tracer;
  tracer->SetInputData(image);
  tracer->SetSourceData(seedData);
  tracer->SetIntegratorTypeToRungeKutta4();
  tracer->SetIntegrationStepUnit(vtkStreamTracer::LENGTH_UNIT);
  tracer->SetInitialIntegrationStep(0.05);
  tracer->SetMaximumNumberOfSteps(maxSteps);
  tracer->SetMaximumPropagation(1e9);
  tracer->SetTerminalSpeed(1e-12);
  tracer->SetIntegrationDirectionToForward();
  tracer->SetComputeVorticity(false);
  const auto start = std::chrono::steady_clock::now();
  tracer->Update();
  const double vtkSeconds = seconds(start);
  vtkPolyData* lines = tracer->GetOutput();
  const long long steps = lines->GetNumberOfPoints() - lines->GetNumberOfLines();
  const double vtkRate = double(steps) / vtkSeconds;

  // Sandstorm's CPU reference: RK4 tracers through the same grid, one core.
  ParticleState state;
  state.sim.integrator = Integrator::RK4;
  state.sim.boundary = BoundaryMode::Clamp;
  state.sim.maximum = 200000;
  Emitter& e = state.emitters[0];
  e.shape = EmitterShape::Disc;
  e.position = {0.0f, 0.0f, 0.5f};
  e.radius = 3.5f;
  e.lifetime = 1000.0f;
  ReferenceSimulator cpu(200000);
  cpu.setField(field);
  SimStep step{0, 1.0f / 60.0f, Seed::from(9), {200000}, 0.0f};
  cpu.step(step, state);
  const int cpuSteps = 20;
  const auto cpuStart = std::chrono::steady_clock::now();
  for (int f = 1; f <= cpuSteps; ++f) {
    step.frame = std::uint32_t(f);
    step.emission = {0};
    cpu.step(step, state);
  }
  const double cpuRate = double(cpu.particles().size()) * cpuSteps / seconds(cpuStart);

  std::printf(
      "vtkStreamTracer (VTK %s), RK4, %d seeds, up to %d steps of 0.05 m: %lld steps in %.3f s = "
      "%.3g "
      "particle-steps/s\n",
      VTK_VERSION, seeds, maxSteps, steps, vtkSeconds, vtkRate);
  std::printf("Sandstorm ReferenceSimulator (CPU, one core), RK4 tracers: %.3g particle-steps/s\n",
              cpuRate);
  std::printf(
      "{\"vtk_rk4_steps_per_s\": %.6g, \"vtk_steps\": %lld, \"vtk_seconds\": %.6g, "
      "\"reference_cpu_rk4_steps_per_s\": %.6g}\n",
      vtkRate, steps, vtkSeconds, cpuRate);
  return 0;
}
