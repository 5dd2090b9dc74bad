// readOpenFoam(): an OpenFOAM case (its folder, its .foam file, or its
// system/controlDict) read by VTK's OpenFOAM readers at options.timeStep:
// the internal mesh (polyhedra decomposed into VTK's cells) with its cell
// fields (U as the flow, the others as scalars to colour by), the time
// folders as time steps (report.times). A case whose mesh is only in
// processor* folders (decomposed for a parallel run, not reconstructed) is
// read from every processor folder and merged.
//
// Before the reader opens it, every file it will read (the polyMesh lists, the
// time folder's fields) is checked by checkOpenFoamFile, so no list claims
// more than its file holds. Throws Error naming the file and what was wrong.
#pragma once

#include <filesystem>

#include <vtkSmartPointer.h>

#include "core/io/load_options.h"

class vtkDataObject;

namespace sandstorm {

vtkSmartPointer<vtkDataObject> readOpenFoam(const std::filesystem::path& path,
                                            const LoadOptions& options, LoadReport& report);

}  // namespace sandstorm
