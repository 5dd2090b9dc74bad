#include "core/io/vtk_xml_reader.h"

#include <vtkDataSet.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkRectilinearGrid.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLRectilinearGridReader.h>
#include <vtkXMLStructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstring>
#include <fstream>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/field/vector_field.h"
#include "core/io/budget_advice.h"
#include "core/io/huge_page_image_reader.h"
#include "core/io/vtk_cell_check.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_progress.h"
#include "core/io/vtk_xml_check.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

template <class Reader>
vtkSmartPointer<vtkDataSet> run(const std::filesystem::path& path, const LoadOptions& options,
                                const std::string& what) {
  const std::string file = path.string();
  // Before VTK allocates what the attributes claim.
  VtkXmlSummary checked = checkVtkXml(path, options.memoryBudget);
  VtkMessageTrap trap(path);
  vtkNew<Reader> reader;
  trap.watch(reader);
  reader->SetFileName(file.c_str());
  if constexpr (std::is_same_v<Reader, HugePageImageReader>)
    reader->setRawArrays(std::move(checked.raw));
  if (!reader->CanReadFile(file.c_str())) {
    trap.throwIfFailed(concat("reading the ", what));
    throw Error(concat(file, ": VTK's reader does not accept it as a ", what));
  }
  reader->UpdateInformation();
  trap.throwIfFailed(concat("reading the structure of the ", what));
  vtkInformation* info = reader->GetOutputInformation(0);
  if (!info || !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    throw Error(concat(file, ": the ", what, " declares no WholeExtent"));
  int extent[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  double points = 1.0;
  for (int a = 0; a < 3; ++a) {
    const long long n = (long long)extent[2 * a + 1] - extent[2 * a] + 1;
    if (n <= 0)
      throw Error(concat(file, ": WholeExtent along ", "xyz"[a], " is ", extent[2 * a], "..",
                         extent[2 * a + 1], "; expected at least one point"));
    points *= double(n);
  }
  if (points > double(VectorField::kMaxPoints) || points * 12.0 > double(options.memoryBudget))
    throw Error(concat(
        file, ": WholeExtent ", extent[0], " ", extent[1], " ", extent[2], " ", extent[3], " ",
        extent[4], " ", extent[5], " holds ", points,
        " points, beyond the memory budget (field.memory_budget) of ", options.memoryBudget,
        " bytes (12 per point, at most ", VectorField::kMaxPoints, " points)",
        points > double(VectorField::kMaxPoints) ? std::string() : raiseBudget(points * 12.0)));
  // The values' count against the extent was held by checkVtkXml (each payload
  // exactly what the piece's extent needs), so VTK reads each array once.
  std::optional<VtkProgress> progress;
  if (options.showProgress) progress.emplace(reader, path);
  reader->Update();
  if (progress) progress->finish();
  trap.throwIfFailed(concat("reading the ", what));
  vtkSmartPointer<vtkDataSet> out = reader->GetOutput();
  if (!out || out->GetNumberOfPoints() != static_cast<vtkIdType>(points))
    throw Error(concat(file, ": VTK read ", out ? out->GetNumberOfPoints() : 0, " points from the ",
                       what, " whose WholeExtent holds ", points));
  return out;
}

// A .vtu or .vtp: the counts and payloads checked first, the cells after.
template <class Reader>
vtkSmartPointer<vtkDataSet> runUnstructured(const std::filesystem::path& path,
                                            const LoadOptions& options, const std::string& what) {
  const std::string file = path.string();
  checkVtkXml(path, options.memoryBudget);
  VtkMessageTrap trap(path);
  vtkNew<Reader> reader;
  trap.watch(reader);
  reader->SetFileName(file.c_str());
  if (!reader->CanReadFile(file.c_str())) {
    trap.throwIfFailed(concat("reading the ", what));
    throw Error(concat(file, ": VTK's reader does not accept it as a ", what));
  }
  reader->Update();
  trap.throwIfFailed(concat("reading the ", what));
  vtkSmartPointer<vtkDataSet> out = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!out) throw Error(concat(file, ": VTK read no ", what));
  checkVtkCells(out, file);
  return out;
}

}  // namespace

vtkSmartPointer<vtkDataSet> readVtkXml(const std::filesystem::path& path, FieldFormat format,
                                       const LoadOptions& options) {
  switch (format) {
    case FieldFormat::VtkImageData:
      return run<HugePageImageReader>(path, options, "VTK XML image data");
    case FieldFormat::VtkRectilinearGrid:
      return run<vtkXMLRectilinearGridReader>(path, options, "VTK XML rectilinear grid");
    case FieldFormat::VtkStructuredGrid:
      return run<vtkXMLStructuredGridReader>(path, options, "VTK XML structured grid");
    case FieldFormat::VtkUnstructuredGrid:
      return runUnstructured<vtkXMLUnstructuredGridReader>(path, options,
                                                           "VTK XML unstructured grid");
    case FieldFormat::VtkPolyData:
      return runUnstructured<vtkXMLPolyDataReader>(path, options, "VTK XML polydata");
    default:
      break;
  }
  throw Error(concat(path.string(), ": readVtkXml() got a ", describe(format)));
}

}  // namespace sandstorm
