#include "core/io/exodus_reader.h"

#include <vtkDataSet.h>
#include <vtkExodusIIReader.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>

#include "core/io/netcdf_header.h"
#include "core/io/vtk_blocks.h"
#include "core/io/vtk_cell_check.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_time_steps.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// What the reader will hold at once, against the budget; and the shape of an
// Exodus file at all.
void checkExodusHeader(const NetcdfHeader& h, const std::string& file, const LoadOptions& options) {
  const auto* dims = h.dimension("num_dim");
  const auto* nodes = h.dimension("num_nodes");
  if (!dims || !nodes)
    throw Error(concat(file,
                       ": a NetCDF file without num_dim and num_nodes: not an Exodus II "
                       "mesh (a NetCDF CF field is named .nc)"));
  if (dims->length < 1 || dims->length > 3)
    throw Error(concat(file, ": num_dim is ", dims->length, "; expected 1, 2 or 3"));
  double bytes = double(nodes->length) * 3.0 * 8.0;
  double nodalVariables = 0.0;
  for (const NetcdfVariable& v : h.variables) {
    if (v.name.rfind("connect", 0) == 0) bytes += h.values(v) * 8.0;
    if (v.name.rfind("vals_nod_var", 0) == 0) nodalVariables += 1.0;
  }
  if (const auto* n = h.dimension("num_nod_var")) nodalVariables = double(n->length);
  bytes += nodalVariables * double(nodes->length) * 8.0;
  if (bytes > double(options.memoryBudget))
    throw Error(concat(file, ": its ", nodes->length, " nodes, their connectivity and one step of ",
                       nodalVariables, " nodal variables need ", bytes,
                       " bytes, beyond the memory budget of ", options.memoryBudget, " bytes"));
}

}  // namespace

vtkSmartPointer<vtkDataObject> readExodus(const std::filesystem::path& path,
                                          const LoadOptions& options, LoadReport& report) {
  const std::string file = path.string();
  checkExodusHeader(readNetcdfHeader(path), file, options);
  VtkMessageTrap trap(path);
  vtkNew<vtkExodusIIReader> reader;
  trap.watch(reader);
  reader->SetFileName(file.c_str());
  // The reader's bookkeeping arrays are no quantity to colour by.
  reader->SetGenerateObjectIdCellArray(0);
  reader->SetGenerateGlobalElementIdArray(0);
  reader->SetGenerateGlobalNodeIdArray(0);
  reader->SetGenerateImplicitElementIdArray(0);
  reader->SetGenerateImplicitNodeIdArray(0);
  reader->SetGenerateFileIdArray(0);
  if (!reader->CanReadFile(file.c_str())) {
    trap.throwIfFailed("opening the Exodus II file");
    throw Error(concat(file, ": VTK's Exodus II reader does not accept it"));
  }
  reader->UpdateInformation();
  trap.throwIfFailed("reading the Exodus II file's structure");
  for (int i = 0; i < reader->GetNumberOfObjects(vtkExodusIIReader::ELEM_BLOCK); ++i)
    reader->SetObjectStatus(vtkExodusIIReader::ELEM_BLOCK, i, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::NODAL, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
  updateAtStep(reader, options, report, file);
  trap.throwIfFailed("reading the Exodus II file");
  vtkSmartPointer<vtkDataObject> out = reader->GetOutputDataObject(0);
  if (!out) throw Error(concat(file, ": VTK's Exodus II reader returned nothing"));
  for (const VtkBlock& b : vtkBlocks(out))
    checkVtkCells(b.data, concat(file, ": ", b.name));
  return out;
}

}  // namespace sandstorm
