// Readers of files that hold several time steps (Exodus, EnSight, OpenFOAM,
// NetCDF, CGNS) advertise their times after UpdateInformation();
// updateAtStep() reads the one options.timeStep names (0: the first) and lists
// them all in report.times, so FieldSequence can read the rest.
#pragma once

#include <string>
#include <vector>

#include "core/io/load_options.h"

class vtkAlgorithm;

namespace sandstorm {

std::vector<double> advertisedTimes(vtkAlgorithm* reader);

// Throws Error naming `file` when options.timeStep is past the last step.
void updateAtStep(vtkAlgorithm* reader, const LoadOptions& options, LoadReport& report,
                  const std::string& file);

}  // namespace sandstorm
