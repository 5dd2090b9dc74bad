#include "core/io/ensight_reader.h"

#include <vtkDataSet.h>
#include <vtkGenericEnSightReader.h>
#include <vtkNew.h>

#include "core/io/ensight_check.h"
#include "core/io/vtk_blocks.h"
#include "core/io/vtk_cell_check.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_time_steps.h"
#include "core/util/error.h"

namespace sandstorm {

vtkSmartPointer<vtkDataObject> readEnSight(const std::filesystem::path& path,
                                           const LoadOptions& options, LoadReport& report) {
  const std::string file = path.string();
  const EnSightCase c = parseEnSightCase(path);
  if (!c.times.empty() && options.timeStep >= c.times.size())
    throw Error(
        concat(file, ": has ", c.times.size(), " time steps; asked for step ", options.timeStep));
  checkEnSightStep(c, options.timeStep, options.memoryBudget);
  VtkMessageTrap trap(path);
  vtkNew<vtkGenericEnSightReader> reader;
  trap.watch(reader);
  reader->SetCaseFileName(file.c_str());
  reader->ReadAllVariablesOn();
  reader->UpdateInformation();
  trap.throwIfFailed("reading the EnSight case's structure");
  vtkSmartPointer<vtkDataObject> out =
      readAtStep(reader, trap, options, report, file, "EnSight case");
  return out;
}

}  // namespace sandstorm
