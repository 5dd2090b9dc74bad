#include "core/io/field_loader.h"

#include <algorithm>

#include <vtkCompositeDataSet.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "core/io/budget_advice.h"
#include "core/io/cgns_reader.h"
#include "core/io/ensight_reader.h"
#include "core/io/exodus_reader.h"
#include "core/io/fga_reader.h"
#include "core/io/field_format.h"
#include "core/io/netcdf_cf_reader.h"
#include "core/io/netcdf_lock.h"
#include "core/io/openfoam_reader.h"
#include "core/io/pvd_file.h"
#include "core/io/unity_vf_reader.h"
#include "core/io/vdb_reader.h"
#include "core/io/vtk_blocks.h"
#include "core/io/vtk_field_extractor.h"
#include "core/io/vtk_legacy_reader.h"
#include "core/io/vtk_xml_index.h"
#include "core/io/vtk_xml_reader.h"
#include "core/io/vtkhdf_reader.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

void checkResolution(const std::string& file, const LoadOptions& options) {
  const glm::ivec3 r = options.resolution;
  if (r == glm::ivec3(0)) return;
  for (int a = 0; a < 3; ++a)
    if (r[a] <= 0)
      throw Error(concat(file, ": field.resolution along ", "xyz"[a], " is ", r[a],
                         "; expected a positive point count (or 0 0 0 for the file's own)"));
  const double points = double(r.x) * r.y * r.z;
  if (points > double(VectorField::kMaxPoints) || points * 12.0 > double(options.memoryBudget))
    throw Error(concat(file, ": the requested ", r.x, "x", r.y, "x", r.z, " grid needs ",
                       points * 12.0, " bytes, beyond the memory budget (field.memory_budget) of ",
                       options.memoryBudget, " bytes; choose a lower field.resolution",
                       points > double(VectorField::kMaxPoints)
                           ? std::string()
                           : concat(", or raise field.memory_budget to at least ",
                                    budgetValueAtLeast(points * 12.0))));
}

// The VTK data a VTK-based format's reader makes of the file; null for the
// formats read otherwise.
vtkSmartPointer<vtkDataObject> readVtkData(const std::filesystem::path& path, FieldFormat format,
                                           LoadOptions& options, LoadReport& report) {
  switch (format) {
    case FieldFormat::VtkLegacy:
      return readVtkLegacy(path, options);
    case FieldFormat::VtkImageData:
    case FieldFormat::VtkRectilinearGrid:
    case FieldFormat::VtkStructuredGrid:
    case FieldFormat::VtkUnstructuredGrid:
    case FieldFormat::VtkPolyData:
      return readVtkXml(path, format, options);
    case FieldFormat::VtkPImageData:
    case FieldFormat::VtkPRectilinearGrid:
    case FieldFormat::VtkPStructuredGrid:
    case FieldFormat::VtkPUnstructuredGrid:
    case FieldFormat::VtkPPolyData:
    case FieldFormat::VtkMultiBlock:
      return readVtkXmlIndex(path, format, options, report);
    case FieldFormat::ExodusII: {
      const auto lock = lockNetcdfLibraries();
      return readExodus(path, options, report);
    }
    case FieldFormat::OpenFoam:
      return readOpenFoam(path, options, report);
    case FieldFormat::EnSightGold:
      return readEnSight(path, options, report);
    case FieldFormat::NetCdf: {
      const auto lock = lockNetcdfLibraries();
      return readNetcdfCf(path, options, report);  // may name the flow's components
    }
    case FieldFormat::VtkHdf: {
      const auto lock = lockNetcdfLibraries();
      return readVtkHdf(path, options, report);
    }
    case FieldFormat::Cgns: {
      const auto lock = lockNetcdfLibraries();
      return readCgns(path, options, report);
    }
    default:
      return nullptr;
  }
}

VectorField dispatch(const std::filesystem::path& path, FieldFormat format,
                     const LoadOptions& options, LoadReport& report) {
  LoadOptions read = options;
  if (vtkSmartPointer<vtkDataObject> data = readVtkData(path, format, read, report))
    return extractVectorField(data, path, read, report);
  switch (format) {
    case FieldFormat::VtkCollection: {
      const std::vector<PvdFrame> frames = readPvd(path);
      report.notes.push_back(concat("time series of ", frames.size(),
                                    " frames: loaded the first (t = ", frames.front().time, ", ",
                                    frames.front().file().filename().string(), ")"));
      LoadReport inner;
      VectorField f = loadFieldParts(frames.front().parts, path, options, &inner);
      report.available = inner.available;
      report.arrayName = inner.arrayName;
      report.sourceDims = inner.sourceDims;
      report.resampled = inner.resampled;
      report.nonFinite = inner.nonFinite;
      report.notes.insert(report.notes.end(), inner.notes.begin(), inner.notes.end());
      report.notesLogged.insert(report.notesLogged.end(), inner.notesLogged.begin(),
                                inner.notesLogged.end());
      return f;
    }
    case FieldFormat::OpenVdb:
      return readVdb(path, options, report);
    case FieldFormat::UnrealFga:
      return readFga(path, options, report);
    case FieldFormat::UnityVf:
      return readUnityVf(path, options, report);
    default:  // Unknown; the VTK-based formats were read above
      break;
  }
  throw Error(concat(path.string(), ": format not recognised; expected ", knownFormats()));
}

// A library's exceptions as the loaders' errors, naming `file`.
template <class Read>
auto guarded(const std::string& file, Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const Error& e) {
    const std::string what = e.what();
    if (what.rfind(file, 0) == 0) throw;
    throw Error(concat(file, ": ", what));
  } catch (const std::bad_alloc&) {
    throw Error(concat(file, ": ran out of memory while loading; lower the resolution ",
                       "(field.resolution)"));
  } catch (const std::exception& e) {
    // A reading library's own exception (VTK's readers throw the standard
    // library's on some malformed files): the file is refused, the run goes on.
    throw Error(concat(file, ": the reader failed: ", e.what()));
  }
}

}  // namespace

VectorField loadFieldParts(const std::vector<std::filesystem::path>& parts,
                           const std::filesystem::path& dataset, const LoadOptions& options,
                           LoadReport* report) {
  const std::string name = dataset.string();
  if (parts.empty()) throw Error(concat(name, ": a dataset of no parts"));
  if (parts.size() == 1) return loadField(parts.front(), options, report);
  checkResolution(name, options);
  LoadReport local;
  LoadReport& r = report ? *report : local;
  r = LoadReport{};
  return guarded(name, [&] {
    const double allowed = 2.0 * double(options.memoryBudget);
    double held = 0.0;  // bytes the parts read so far take
    vtkNew<vtkMultiBlockDataSet> blocks;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const std::filesystem::path& part = parts[i];
      const std::string where = concat(name, ": part ", i, " (", part.string(), ")");
      std::error_code ec;
      if (!std::filesystem::is_regular_file(part, ec)) throw Error(concat(where, ": no such file"));
      const FieldFormat format = detectFieldFormat(part);
      checkExtension(part, format);
      LoadOptions read = options;  // each part checked against the budget before it is read
      LoadReport partReport;
      const vtkSmartPointer<vtkDataObject> data =
          guarded(part.string(), [&] { return readVtkData(part, format, read, partReport); });
      if (!data)
        throw Error(concat(where, " is ", describe(format),
                           "; a dataset's parts are VTK files (.vti .vtr .vts .vtu .vtp .vtk, "
                           "parallel .pvt?, .vtm)"));
      held += 1024.0 * double(data->GetActualMemorySize());
      if (held > allowed)
        throw Error(concat(where, ": the parts up to it take ", held,
                           " bytes, beyond twice the memory budget (field.memory_budget) of ",
                           options.memoryBudget, " bytes that a dataset's parts may take",
                           raiseBudget(held / 2.0)));
      for (const VtkBlock& b : vtkBlocks(data)) {
        const unsigned at = blocks->GetNumberOfBlocks();
        blocks->SetBlock(at, b.data);
        blocks->GetMetaData(at)->Set(vtkCompositeDataSet::NAME(),
                                     concat("part ", i, " (", part.filename().string(), ")",
                                            b.name.empty() ? std::string() : ": " + b.name)
                                         .c_str());
      }
    }
    VectorField field = extractVectorField(blocks, dataset, options, r);
    r.format = concat(describe(detectFieldFormat(parts.front())), ", ", parts.size(), " parts");
    r.notes.push_back(concat(parts.size(), " parts read and resampled together"));
    if (options.halfPrecision && !field.halfPrecision()) field.roundToHalf();
    log::debug("loaded ", name, " (", r.format, "): ", field.dims().x, "x", field.dims().y, "x",
               field.dims().z, " points");
    return field;
  });
}

VectorField loadField(const std::filesystem::path& path, const LoadOptions& options,
                      LoadReport* report) {
  const std::string file = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(concat(file, ": no such file"));
  const bool folder = std::filesystem::is_directory(path, ec);
  if (!folder && !std::filesystem::is_regular_file(path, ec))
    throw Error(concat(file, ": not a regular file"));
  const FieldFormat format = detectFieldFormat(path);
  if (folder && format != FieldFormat::OpenFoam)
    throw Error(concat(file,
                       ": a folder, and not an OpenFOAM case (no system/controlDict); "
                       "expected ",
                       knownFormats()));
  checkExtension(path, format);
  checkResolution(file, options);
  LoadReport local;
  LoadReport& r = report ? *report : local;
  r = LoadReport{};
  return guarded(file, [&] {
    VectorField field = dispatch(path, format, options, r);
    if (r.format.empty()) r.format = describe(format);
    // A .vti's floats are rounded as they are checked (vtk_field_extractor).
    if (options.halfPrecision && !field.halfPrecision()) field.roundToHalf();
    log::debug("loaded ", file, " (", r.format, "): ", field.dims().x, "x", field.dims().y, "x",
               field.dims().z, " points");
    return field;
  });
}

}  // namespace sandstorm
