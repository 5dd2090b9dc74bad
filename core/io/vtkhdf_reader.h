// readVtkHdf(): a VTKHDF file (.vtkhdf, .hdf: VTK's HDF5 format, version 1,
// image data or an unstructured grid in pieces) read by VTK's vtkHDFReader.
//
// Before the reader runs, the file's layout is asked through the HDF5
// library (which reads metadata only) and checked: the /VTKHDF group's
// Version and Type; an image's WholeExtent against every point and cell
// array's shape; an unstructured grid's per-piece NumberOfPoints,
// NumberOfCells and NumberOfConnectivityIds against the shapes of Points,
// Types, Offsets, Connectivity and every point and cell array; everything
// within the memory budget; then each piece's Offsets (from 0 up to its
// connectivity) and Connectivity (its own points) are read and checked,
// because VTK builds its cells from them unchecked. Throws Error naming the
// file, the dataset and what was wrong.
#pragma once

#include <filesystem>

#include <vtkSmartPointer.h>

#include "core/io/load_options.h"

class vtkDataObject;

namespace sandstorm {

vtkSmartPointer<vtkDataObject> readVtkHdf(const std::filesystem::path& path,
                                          const LoadOptions& options, LoadReport& report);

}  // namespace sandstorm
