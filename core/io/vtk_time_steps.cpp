#include "core/io/vtk_time_steps.h"

#include <vtkAlgorithm.h>
#include <vtkInformation.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include "core/util/error.h"

namespace sandstorm {

std::vector<double> advertisedTimes(vtkAlgorithm* reader) {
  vtkInformation* info = reader->GetOutputInformation(0);
  if (!info || !info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS())) return {};
  const int n = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const double* t = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  return std::vector<double>(t, t + n);
}

void updateAtStep(vtkAlgorithm* reader, const LoadOptions& options, LoadReport& report,
                  const std::string& file) {
  report.times = advertisedTimes(reader);
  if (report.times.empty()) {
    if (options.timeStep > 0)
      throw Error(concat(file, ": has no time steps; asked for step ", options.timeStep));
    reader->Update();
    return;
  }
  if (options.timeStep >= report.times.size())
    throw Error(concat(file, ": has ", report.times.size(), " time steps; asked for step ",
                       options.timeStep));
  reader->UpdateTimeStep(report.times[options.timeStep]);
}

}  // namespace sandstorm
