#include "core/io/vtk_time_steps.h"

#include <vtkAlgorithm.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkInformation.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include "core/io/vtk_blocks.h"
#include "core/io/vtk_cell_check.h"
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

vtkSmartPointer<vtkDataObject> readAtStep(vtkAlgorithm* reader, const VtkMessageTrap& trap,
                                          const LoadOptions& options, LoadReport& report,
                                          const std::string& file, const std::string& what) {
  updateAtStep(reader, options, report, file);
  trap.throwIfFailed(concat("reading the ", what));
  vtkSmartPointer<vtkDataObject> out = reader->GetOutputDataObject(0);
  if (!out) throw Error(concat(file, ": VTK's reader of the ", what, " returned nothing"));
  for (const VtkBlock& b : vtkBlocks(out))
    checkVtkCells(b.data, concat(file, ": ", b.name));
  return out;
}

}  // namespace sandstorm
