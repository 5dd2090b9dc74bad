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
#include <vector>

#include "core/field/vector_field.h"
#include "core/io/vtk_cell_check.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_xml_check.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// VTK reads as many values as the extent asks for and ignores any surplus, so
// an extent smaller than the data loads silently. Each point array of a single
// piece is asked here, through VTK's own parser, for one word more than the
// points need: getting it means the file holds more values than points.
void checkValueCounts(vtkXMLDataParser* parser, double points, const std::string& file) {
  if (!parser || !parser->GetRootElement()) return;
  vtkXMLDataElement* dataset = parser->GetRootElement()->GetNestedElement(0);
  if (!dataset || dataset->GetNumberOfNestedElements() != 1) return;  // several pieces
  vtkXMLDataElement* piece = dataset->GetNestedElement(0);
  vtkXMLDataElement* pointData = piece ? piece->FindNestedElementWithName("PointData") : nullptr;
  if (!pointData) return;
  // The reader has closed its stream by now: lend the parser one of ours.
  std::ifstream stream(file, std::ios::binary);
  if (!stream) return;
  std::istream* previous = parser->GetStream();
  parser->SetStream(&stream);
  struct Restore {
    vtkXMLDataParser* parser;
    std::istream* previous;
    ~Restore() { parser->SetStream(previous); }
  } restore{parser, previous};
  for (int i = 0; i < pointData->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* array = pointData->GetNestedElement(i);
    if (std::strcmp(array->GetName(), "DataArray") != 0) continue;
    int wordType = 0, components = 1;
    if (!array->GetWordTypeAttribute("type", wordType)) continue;
    array->GetScalarAttribute("NumberOfComponents", components);
    const int wordSize = vtkAbstractArray::GetDataTypeSize(wordType);
    const double words = points * std::max(components, 1);
    if (wordSize <= 0 || words <= 0 || words > 1e9) continue;
    const std::size_t ask = std::size_t(words) + 1;
    std::vector<unsigned char> buffer(ask * std::size_t(wordSize));
    const char* format = array->GetAttribute("format");
    std::size_t got = 0;
    if (format && std::strcmp(format, "appended") == 0) {
      vtkTypeInt64 offset = 0;
      if (!array->GetScalarAttribute("offset", offset)) continue;
      got = parser->ReadAppendedData(offset, buffer.data(), 0, ask, wordType);
    } else {
      got = parser->ReadInlineData(array, format && std::strcmp(format, "ascii") == 0,
                                   buffer.data(), 0, ask, wordType);
    }
    if (got > std::size_t(words)) {
      const char* name = array->GetAttribute("Name");
      throw Error(concat(file, ": point array '", name ? name : "", "' holds more than the ", words,
                         " values its ", points, " points need; the extent and the data ",
                         "disagree (value count differs from the point count)"));
    }
  }
}

template <class Reader>
vtkSmartPointer<vtkDataSet> run(const std::filesystem::path& path, const LoadOptions& options,
                                const std::string& what) {
  const std::string file = path.string();
  checkVtkXml(path, options.memoryBudget);  // before VTK allocates what the attributes claim
  VtkMessageTrap trap(path);
  vtkNew<Reader> reader;
  trap.watch(reader);
  reader->SetFileName(file.c_str());
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
    throw Error(concat(file, ": WholeExtent ", extent[0], " ", extent[1], " ", extent[2], " ",
                       extent[3], " ", extent[4], " ", extent[5], " holds ", points,
                       " points, beyond the memory budget (field.memory_budget) of ",
                       options.memoryBudget, " bytes (12 per point, at most ",
                       VectorField::kMaxPoints, " points)"));
  reader->Update();
  trap.throwIfFailed(concat("reading the ", what));
  checkValueCounts(reader->GetXMLParser(), points, file);
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
      return run<vtkXMLImageDataReader>(path, options, "VTK XML image data");
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
