// readVtkXmlIndex(): the VTK XML files that name other files, read by VTK's
// own readers: the parallel files (.pvti .pvtr .pvts .pvtu .pvtp: pieces of
// one dataset; a .pvti's merged into one image, the others' read several at
// once and kept as the partitions of a vtkPartitionedDataSet, vtk_xml_pieces.h)
// and multiblock files (.vtm: blocks of any kind, kept as blocks for
// extractVectorField to merge).
//
// Before VTK opens a piece or block, the index is parsed (VTK's XML parser)
// and every file it names is checked:
// - the name is not empty, and stays inside the index's folder tree (no
//   "..", no absolute path elsewhere);
// - the file exists, is a regular file, is not the index itself;
// - its content is the kind the index needs (a .pvtu's pieces .vtu, ...; a
//   .vtm's blocks any single-dataset XML file: VTK reads no .vtm as a block);
// - checkVtkXml passes it, and all the files' arrays together fit twice the
//   memory budget;
// - a piece holds every array its parallel index declares (PPoints,
//   PPointData, PCellData, PCoordinates), of the declared type and
//   components: VTK copies pieces into arrays made as declared, and a
//   mismatch (Float64 points under a Float32 declaration) crashes it.
// Once read, every block's cells are checked (checkVtkCells). Errors name the
// index, the piece or block and its file, and what was wrong. Ghost cells
// that pieces share stay marked (vtkGhostType); the resampler skips them.
#pragma once

#include <filesystem>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/io/field_format.h"
#include "core/io/load_options.h"

class vtkDataObject;

namespace sandstorm {

vtkSmartPointer<vtkDataObject> readVtkXmlIndex(const std::filesystem::path& path,
                                               FieldFormat format, const LoadOptions& options,
                                               LoadReport& report);

// The files an index names, checked as above (without reading them).
std::vector<std::filesystem::path> vtkXmlIndexFiles(const std::filesystem::path& path,
                                                    FieldFormat format);

}  // namespace sandstorm
