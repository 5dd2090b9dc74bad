#include "core/io/openfoam_reader.h"

#include <array>
#include <map>

#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkDummyController.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOpenFOAMReader.h>
#include <vtkPOpenFOAMReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include "core/io/openfoam_check.h"
#include "core/io/vtk_blocks.h"
#include "core/io/vtk_cell_check.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_time_steps.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

namespace fs = std::filesystem;

fs::path caseFolder(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return path;
  if (path.filename() == "controlDict") return path.parent_path().parent_path();
  return path.parent_path().empty() ? fs::path(".") : path.parent_path();
}

bool hasProcessorFolders(const fs::path& folder) {
  std::error_code ec;
  return fs::is_directory(folder / "processor0", ec);
}

template <class Reader>
void configure(Reader* reader, const std::string& controlFile) {
  reader->SetFileName(controlFile.c_str());
  // Sandstorm moves cell data to the points itself, as for every format.
  reader->CreateCellToPointOff();
  reader->DecomposePolyhedraOn();
  reader->ReadZonesOff();
}

// The processors' meshes meet at faces whose points each holds a copy of.
// Merged (points of equal coordinates made one), the cells on both sides
// share them, so moving cell data to the points averages across the seam as
// it does inside one processor's mesh. A grid with polyhedra is left as it is.
vtkSmartPointer<vtkUnstructuredGrid> mergeCoincidentPoints(vtkUnstructuredGrid* grid) {
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    if (grid->GetCellType(c) == VTK_POLYHEDRON) return grid;
  std::map<std::array<double, 3>, vtkIdType> ids;
  std::vector<vtkIdType> remap(std::size_t(grid->GetNumberOfPoints()));
  vtkNew<vtkPoints> points;
  points->SetDataType(grid->GetPoints()->GetDataType());
  vtkNew<vtkIdList> kept;
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p) {
    std::array<double, 3> x;
    grid->GetPoint(p, x.data());
    const auto [it, added] = ids.emplace(x, points->GetNumberOfPoints());
    if (added) {
      points->InsertNextPoint(x.data());
      kept->InsertNextId(p);
    }
    remap[std::size_t(p)] = it->second;
  }
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->SetPoints(points);
  out->GetPointData()->CopyAllocate(grid->GetPointData(), kept->GetNumberOfIds());
  for (vtkIdType i = 0; i < kept->GetNumberOfIds(); ++i)
    out->GetPointData()->CopyData(grid->GetPointData(), kept->GetId(i), i);
  out->Allocate(grid->GetNumberOfCells());
  vtkNew<vtkIdList> cell;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    grid->GetCellPoints(c, cell);
    for (vtkIdType i = 0; i < cell->GetNumberOfIds(); ++i)
      cell->SetId(i, remap[std::size_t(cell->GetId(i))]);
    out->InsertNextCell(grid->GetCellType(c), cell);
  }
  out->GetCellData()->ShallowCopy(grid->GetCellData());
  return out;
}

vtkSmartPointer<vtkDataObject> mergeProcessorSeams(vtkDataObject* data) {
  auto merged = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  const std::vector<VtkBlock> blocks = vtkBlocks(data);
  merged->SetNumberOfBlocks(unsigned(blocks.size()));
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    vtkDataSet* block = blocks[i].data;
    if (auto* grid = vtkUnstructuredGrid::SafeDownCast(block))
      merged->SetBlock(unsigned(i), mergeCoincidentPoints(grid));
    else
      merged->SetBlock(unsigned(i), block);
    merged->GetMetaData(unsigned(i))->Set(vtkCompositeDataSet::NAME(), blocks[i].name.c_str());
  }
  return merged;
}

}  // namespace

vtkSmartPointer<vtkDataObject> readOpenFoam(const fs::path& path, const LoadOptions& options,
                                            LoadReport& report) {
  const fs::path folder = caseFolder(path);
  const std::string file = path.string();
  std::error_code ec;
  const fs::path control = folder / "system" / "controlDict";
  if (!fs::is_regular_file(control, ec))
    throw Error(concat(file, ": an OpenFOAM case needs system/controlDict in ", folder.string()));
  const bool decomposed =
      !fs::is_directory(folder / "constant" / "polyMesh", ec) && hasProcessorFolders(folder);
  if (!decomposed && !fs::is_directory(folder / "constant" / "polyMesh", ec))
    throw Error(concat(file,
                       ": the OpenFOAM case has no constant/polyMesh (nor processor* "
                       "folders of a decomposed case)"));
  checkOpenFoamFile(control, options.memoryBudget);
  for (const OpenFoamRoot& r : openFoamFilesToRead(folder, decomposed, options.timeStep)) {
    const std::uint64_t cells = checkOpenFoamMesh(r.root, options.memoryBudget);
    for (const fs::path& f : r.fields) {
      const OpenFoamFacts facts = checkOpenFoamFile(f, options.memoryBudget);
      if (facts.internalField && *facts.internalField != cells)
        throw Error(concat(f.string(), ": internalField holds ", *facts.internalField,
                           " values for the mesh's ", cells, " cells"));
    }
  }

  VtkMessageTrap trap(path);
  vtkSmartPointer<vtkAlgorithm> algorithm;
  vtkNew<vtkDummyController> controller;  // one process reads every processor folder
  if (decomposed) {
    auto reader = vtkSmartPointer<vtkPOpenFOAMReader>::New();
    configure(reader.Get(), control.string());
    reader->SetController(controller);
    reader->SetCaseType(vtkPOpenFOAMReader::DECOMPOSED_CASE);
    algorithm = reader;
    report.notes.push_back("a decomposed case: the processor folders' meshes merged");
  } else {
    auto reader = vtkSmartPointer<vtkOpenFOAMReader>::New();
    configure(reader.Get(), control.string());
    algorithm = reader;
  }
  trap.watch(algorithm);
  algorithm->UpdateInformation();
  trap.throwIfFailed("reading the OpenFOAM case's structure");
  vtkSmartPointer<vtkDataObject> out =
      readAtStep(algorithm, trap, options, report, file, "OpenFOAM case");
  if (decomposed) return mergeProcessorSeams(out);
  return out;
}

}  // namespace sandstorm
