// Readers of files that hold several time steps (Exodus, EnSight, OpenFOAM,
// NetCDF, CGNS) advertise their times after UpdateInformation();
// updateAtStep() reads the one options.timeStep names (0: the first) and lists
// them all in report.times, so FieldSequence can read the rest.
#pragma once

#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/io/load_options.h"
#include "core/io/vtk_message_trap.h"

class vtkAlgorithm;
class vtkDataObject;

namespace sandstorm {

std::vector<double> advertisedTimes(vtkAlgorithm* reader);

// Throws Error naming `file` when options.timeStep is past the last step.
void updateAtStep(vtkAlgorithm* reader, const LoadOptions& options, LoadReport& report,
                  const std::string& file);

// updateAtStep(), then the reader's output with every block's cells checked
// (checkVtkCells); `trap` watches the reader; `what` names the file's kind in
// messages ("Exodus II file").
vtkSmartPointer<vtkDataObject> readAtStep(vtkAlgorithm* reader, const VtkMessageTrap& trap,
                                          const LoadOptions& options, LoadReport& report,
                                          const std::string& file, const std::string& what);

}  // namespace sandstorm
