#include "core/io/vtk_xml_pieces.h"

#include <atomic>
#include <memory>
#include <optional>
#include <system_error>

#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkPartitionedDataSet.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLRectilinearGridReader.h>
#include <vtkXMLStructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "core/io/vtk_cell_check.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_progress.h"
#include "core/util/error.h"
#include "core/util/parallel_for.h"
#include "core/util/progress_meter.h"

namespace sandstorm {
namespace {

template <class Reader>
vtkSmartPointer<vtkDataSet> readWith(const VtkXmlPiece& piece, ProgressMeter* meter) {
  const std::string file = piece.file.string();
  VtkMessageTrap trap(piece.file);  // this thread's VTK messages
  vtkNew<Reader> reader;
  trap.watch(reader);
  reader->SetFileName(file.c_str());
  std::optional<VtkProgress> progress;
  if (meter) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(piece.file, ec);
    progress.emplace(reader, *meter, ec ? 0.0 : double(bytes));
  }
  reader->Update();
  trap.throwIfFailed(concat("reading it as ", piece.where));
  vtkSmartPointer<vtkDataSet> out = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!out) throw Error(concat(piece.where, ": VTK read no dataset from it"));
  checkVtkCells(out, piece.where);  // here, so that the pieces are checked at once too
  return out;
}

vtkSmartPointer<vtkDataSet> readPiece(const VtkXmlPiece& piece, FieldFormat format,
                                      ProgressMeter* meter) {
  switch (format) {
    case FieldFormat::VtkRectilinearGrid:
      return readWith<vtkXMLRectilinearGridReader>(piece, meter);
    case FieldFormat::VtkStructuredGrid:
      return readWith<vtkXMLStructuredGridReader>(piece, meter);
    case FieldFormat::VtkUnstructuredGrid:
      return readWith<vtkXMLUnstructuredGridReader>(piece, meter);
    case FieldFormat::VtkPolyData:
      return readWith<vtkXMLPolyDataReader>(piece, meter);
    default:
      throw Error(concat(piece.where, ": readVtkXmlPieces() got a ", describe(format)));
  }
}

}  // namespace

vtkSmartPointer<vtkPartitionedDataSet> readVtkXmlPieces(const std::vector<VtkXmlPiece>& pieces,
                                                        FieldFormat format, const std::string& what,
                                                        bool showProgress) {
  double bytes = 0.0;
  for (const VtkXmlPiece& p : pieces) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(p.file, ec);
    bytes += ec ? 0.0 : double(size);
  }
  std::unique_ptr<ProgressMeter> meter;
  if (showProgress) meter = std::make_unique<ProgressMeter>(what, std::uint64_t(bytes), "bytes");

  std::vector<vtkSmartPointer<vtkDataSet>> read(pieces.size());
  std::vector<std::string> errors(pieces.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  // One piece a thread at a time, taken in order as threads come free.
  forChunks(
      pieces.size(),
      [&](std::size_t, std::size_t) {
        for (std::size_t i; !failed && (i = next.fetch_add(1)) < pieces.size();) {
          try {
            read[i] = readPiece(pieces[i], format, meter.get());
          } catch (const std::exception& e) {
            errors[i] = e.what();
            failed = true;
          }
        }
      },
      1);
  for (const std::string& e : errors)
    if (!e.empty()) throw Error(e);
  if (meter) meter->finish();

  auto out = vtkSmartPointer<vtkPartitionedDataSet>::New();
  out->SetNumberOfPartitions(unsigned(pieces.size()));
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    out->SetPartition(unsigned(i), read[i]);
    out->GetMetaData(unsigned(i))->Set(vtkCompositeDataSet::NAME(), pieces[i].name.c_str());
  }
  return out;
}

}  // namespace sandstorm
