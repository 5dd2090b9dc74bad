#include "core/io/vtk_field_extractor.h"

#include <cmath>

#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRectilinearGrid.h>
#include <vtkResampleToImage.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>

#include "core/io/vtk_message_trap.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

std::string inventory(vtkDataSet* data) {
  std::string out;
  auto list = [&](vtkFieldData* fd, const char* where) {
    for (int i = 0; i < fd->GetNumberOfArrays(); ++i) {
      vtkAbstractArray* a = fd->GetAbstractArray(i);
      if (!out.empty()) out += ", ";
      out += concat("'", a->GetName() ? a->GetName() : "", "' (", a->GetNumberOfComponents(),
                    a->GetNumberOfComponents() == 1 ? " component" : " components", where, ")");
    }
  };
  list(data->GetPointData(), "");
  list(data->GetCellData(), ", cell data");
  return out.empty() ? "none" : out;
}

void listArrays(vtkDataSet* data, LoadReport& report) {
  auto list = [&](vtkFieldData* fd, const char* where) {
    for (int i = 0; i < fd->GetNumberOfArrays(); ++i) {
      vtkAbstractArray* a = fd->GetAbstractArray(i);
      report.available.push_back(concat(a->GetName() ? a->GetName() : "(unnamed)", " (",
                                        a->GetNumberOfComponents(), " components", where, ")"));
    }
  };
  list(data->GetPointData(), "");
  list(data->GetCellData(), ", cell data");
}

int scalarArrays(vtkPointData* pd) {
  int n = 0;
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
    if (vtkDataArray* a = pd->GetArray(i); a && a->GetNumberOfComponents() == 1) ++n;
  return n;
}

std::vector<std::string> vectorArrays(vtkFieldData* fd) {
  std::vector<std::string> names;
  for (int i = 0; i < fd->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* a = fd->GetAbstractArray(i);
    if (vtkDataArray::SafeDownCast(a) && a->GetNumberOfComponents() == 3 && a->GetName())
      names.emplace_back(a->GetName());
  }
  return names;
}

vtkSmartPointer<vtkDataSet> cellsToPoints(vtkDataSet* data, const std::filesystem::path& path) {
  VtkMessageTrap trap(path);
  vtkNew<vtkCellDataToPointData> filter;
  trap.watch(filter);
  filter->SetInputData(data);
  filter->PassCellDataOff();
  filter->Update();
  trap.throwIfFailed("moving cell data to the points (vtkCellDataToPointData)");
  return filter->GetOutput();
}

struct Chosen {
  vtkSmartPointer<vtkDataSet> data;  // the dataset holding the array in its point data
  std::string name;
};

Chosen chooseArray(vtkDataSet* data, const std::filesystem::path& path, const LoadOptions& options,
                   LoadReport& report) {
  const std::string file = path.string();
  vtkPointData* pd = data->GetPointData();
  vtkCellData* cd = data->GetCellData();
  std::string name = options.arrayName;
  bool fromCells = false;
  if (name.empty()) {
    if (vtkDataArray* active = pd->GetVectors(); active && active->GetName()) {
      name = active->GetName();
      if (const std::vector<std::string> names = vectorArrays(pd); names.size() > 1) {
        std::string all;
        for (const std::string& n : names)
          all += concat(all.empty() ? "'" : ", '", n, "'");
        report.notes.push_back(concat("vector array '", name, "' (the file's active vectors) of ",
                                      all, "; --array NAME chooses another"));
      }
    } else {
      std::vector<std::string> names = vectorArrays(pd);
      if (names.empty()) {
        names = vectorArrays(cd);
        fromCells = true;
      }
      if (names.size() != 1)
        throw Error(
            concat(file, ": ",
                   names.empty() ? "no 3-component (vector) array"
                                 : "several vector arrays and none marked active",
                   "; choose one by name (--array NAME, or the config's field.name). Arrays "
                   "present: ",
                   inventory(data)));
      name = names.front();
    }
  } else if (!pd->GetAbstractArray(name.c_str())) {
    if (!cd->GetAbstractArray(name.c_str()))
      throw Error(concat(file, ": no array named '", name, "'; arrays present: ", inventory(data)));
    fromCells = true;
  }
  vtkAbstractArray* array =
      fromCells ? cd->GetAbstractArray(name.c_str()) : pd->GetAbstractArray(name.c_str());
  if (!vtkDataArray::SafeDownCast(array))
    throw Error(concat(file, ": array '", name, "' is not numeric; expected a 3-component ",
                       "vector array. Arrays present: ", inventory(data)));
  if (array->GetNumberOfComponents() != 3)
    throw Error(concat(
        file, ": array '", name, "' has ", array->GetNumberOfComponents(),
        " component(s); expected a 3-component vector array. Arrays present: ", inventory(data)));
  if (fromCells) {
    report.notes.push_back(concat("array '", name, "' is cell data: moved to the points"));
    return {cellsToPoints(data, path), name};
  }
  // Scalar arrays in cell data (a simulation's pressure per cell) move to the
  // points too, as ParaView's Cell Data to Point Data does, to colour by them.
  for (int i = 0; i < cd->GetNumberOfArrays(); ++i)
    if (vtkDataArray* a = cd->GetArray(i); a && a->GetNumberOfComponents() == 1 && a->GetName()) {
      report.notes.push_back("cell-data scalar arrays moved to the points");
      return {cellsToPoints(data, path), name};
    }
  return {data, name};
}

// Copies tuples into `out`, zeroing non-finite ones and those `mask` marks invalid.
std::size_t copyVectors(vtkDataArray* array, vtkDataArray* mask, std::vector<glm::vec3>& out) {
  std::size_t nonFinite = 0;
  const vtkIdType n = array->GetNumberOfTuples();
  out.resize(std::size_t(n));
  double t[3];
  for (vtkIdType i = 0; i < n; ++i) {
    if (mask && mask->GetComponent(i, 0) == 0.0) {
      out[std::size_t(i)] = glm::vec3(0.0f);
      continue;
    }
    array->GetTuple(i, t);
    const glm::vec3 v(static_cast<float>(t[0]), static_cast<float>(t[1]), static_cast<float>(t[2]));
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      ++nonFinite;
      out[std::size_t(i)] = glm::vec3(0.0f);
    } else {
      out[std::size_t(i)] = v;
    }
  }
  return nonFinite;
}

// VTK's validity mask (vtkResampleToImage's output, or a file that carries
// one, as our converted files do): 1 where the point has data.
constexpr const char* kValidMaskName = "vtkValidPointMask";

std::vector<std::uint8_t> validityOf(vtkDataArray* mask) {
  std::vector<std::uint8_t> valid;
  if (!mask) return valid;
  valid.resize(std::size_t(mask->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i)
    valid[std::size_t(i)] = mask->GetComponent(i, 0) != 0.0 ? 1 : 0;
  return valid;
}

// Every named one-component numeric point array but VTK's own (vtkGhostType,
// vtkValidPointMask: names VTK reserves start with "vtk"), as the field's
// scalar arrays (VectorField::addScalars); non-finite values and points the
// mask marks invalid become zero, counted and logged.
void copyScalars(vtkPointData* pd, vtkDataArray* mask, vtkIdType points,
                 const std::filesystem::path& path, VectorField& field, LoadReport& report) {
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = pd->GetArray(i);
    if (!a || !a->GetName() || a->GetNumberOfComponents() != 1 ||
        a->GetNumberOfTuples() != points || std::string_view(a->GetName()).starts_with("vtk") ||
        field.findScalars(a->GetName()))
      continue;
    std::vector<float> values(std::size_t(points), 0.0f);
    std::size_t nonFinite = 0;
    for (vtkIdType p = 0; p < points; ++p) {
      if (mask && mask->GetComponent(p, 0) == 0.0) continue;
      const float v = float(a->GetComponent(p, 0));
      if (std::isfinite(v))
        values[std::size_t(p)] = v;
      else
        ++nonFinite;
    }
    if (nonFinite > 0)
      log::warn(path.string(), ": ", nonFinite, " values of array '", a->GetName(),
                "' are NaN, Inf or beyond a float; replaced by zero");
    report.nonFinite += nonFinite;
    field.addScalars(a->GetName(), std::move(values));
  }
}

void noteOutside(const VectorField& field, const std::filesystem::path& path, LoadReport& report) {
  report.outside = field.invalidCount();
  if (report.outside == 0) return;
  const std::string note =
      concat(report.outside, " of ", field.pointCount(),
             " points lie outside the file's cells: marked outside the field (particles there "
             "follow sim.boundary)");
  report.notes.push_back(note);
  log::info(path.string(), ": ", note);
}

// `perPoint`: bytes a point takes (12 for the vector, 4 per scalar array).
void checkBudget(const glm::ivec3& dims, const std::filesystem::path& path,
                 const LoadOptions& options, double perPoint) {
  for (int a = 0; a < 3; ++a)
    if (dims[a] <= 0)
      throw Error(concat(path.string(), ": resolution along ", "xyz"[a], " is ", dims[a],
                         "; expected a positive point count"));
  const double points = double(dims.x) * dims.y * dims.z;
  if (points > double(VectorField::kMaxPoints) || points * perPoint > double(options.memoryBudget))
    throw Error(concat(path.string(), ": a ", dims.x, "x", dims.y, "x", dims.z, " grid needs ",
                       points * perPoint, " bytes, beyond the memory budget of ",
                       options.memoryBudget,
                       " bytes; choose a lower resolution (LoadOptions::resolution, --dims)"));
}

glm::ivec3 nativeDims(vtkDataSet* data) {
  int d[3] = {0, 0, 0};
  if (auto* image = vtkImageData::SafeDownCast(data))
    image->GetDimensions(d);
  else if (auto* rect = vtkRectilinearGrid::SafeDownCast(data))
    rect->GetDimensions(d);
  else if (auto* grid = vtkStructuredGrid::SafeDownCast(data))
    grid->GetDimensions(d);
  return {d[0], d[1], d[2]};
}

void reportNonFinite(std::size_t count, const std::filesystem::path& path, const std::string& name,
                     LoadReport& report) {
  report.nonFinite += count;
  if (count > 0)
    log::warn(path.string(), ": ", count, " vectors of array '", name,
              "' are NaN or Inf; replaced by zero");
}

VectorField copyImage(vtkImageData* image, const std::string& name,
                      const std::filesystem::path& path, LoadReport& report) {
  const std::string file = path.string();
  int extent[6];
  image->GetExtent(extent);
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  const glm::ivec3 dims = nativeDims(image);
  vtkMatrix3x3* direction = image->GetDirectionMatrix();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (direction && direction->GetElement(r, c) != (r == c ? 1.0 : 0.0))
        throw Error(concat(file,
                           ": the image's Direction is not the identity; only "
                           "axis-aligned images are read"));
  Box bounds;
  for (int a = 0; a < 3; ++a) {
    if (dims[a] > 1 && !(spacing[a] > 0.0))
      throw Error(concat(file, ": spacing along ", "xyz"[a], " is ", spacing[a],
                         "; expected a positive spacing"));
    bounds.min[a] = float(origin[a] + spacing[a] * extent[2 * a]);
    bounds.max[a] = float(origin[a] + spacing[a] * extent[2 * a + 1]);
  }
  vtkDataArray* array = image->GetPointData()->GetArray(name.c_str());
  if (array->GetNumberOfTuples() != image->GetNumberOfPoints())
    throw Error(concat(file, ": array '", name, "' holds ", array->GetNumberOfTuples(),
                       " vectors for ", image->GetNumberOfPoints(), " grid points"));
  vtkDataArray* mask = image->GetPointData()->GetArray(kValidMaskName);
  if (mask && mask->GetNumberOfTuples() != image->GetNumberOfPoints()) mask = nullptr;
  std::vector<glm::vec3> values;
  reportNonFinite(copyVectors(array, mask, values), path, name, report);
  VectorField field(bounds, dims, std::move(values));
  field.setValidity(validityOf(mask));
  copyScalars(image->GetPointData(), mask, image->GetNumberOfPoints(), path, field, report);
  noteOutside(field, path, report);
  return field;
}

}  // namespace

VectorField extractVectorField(vtkDataSet* data, const std::filesystem::path& path,
                               const LoadOptions& options, LoadReport& report) {
  const std::string file = path.string();
  listArrays(data, report);
  const Chosen chosen = chooseArray(data, path, options, report);
  report.arrayName = chosen.name;
  report.sourceDims = nativeDims(data);

  vtkDataArray* array = chosen.data->GetPointData()->GetArray(chosen.name.c_str());
  if (array->GetNumberOfTuples() != chosen.data->GetNumberOfPoints())
    throw Error(concat(file, ": array '", chosen.name, "' holds ", array->GetNumberOfTuples(),
                       " vectors for ", chosen.data->GetNumberOfPoints(), " grid points"));

  const bool keep = options.resolution == glm::ivec3(0) || options.resolution == report.sourceDims;
  if (auto* image = vtkImageData::SafeDownCast(chosen.data); image && keep)
    return copyImage(image, chosen.name, path, report);

  const glm::ivec3 dims =
      options.resolution == glm::ivec3(0) ? report.sourceDims : options.resolution;
  checkBudget(dims, path, options, 12.0 + 4.0 * scalarArrays(chosen.data->GetPointData()));
  VtkMessageTrap trap(path);
  vtkNew<vtkResampleToImage> resample;
  trap.watch(resample);
  resample->SetInputDataObject(chosen.data);
  resample->UseInputBoundsOn();
  resample->SetSamplingDimensions(dims.x, dims.y, dims.z);
  resample->Update();
  trap.throwIfFailed("resampling to a uniform grid (vtkResampleToImage)");
  vtkImageData* image = resample->GetOutput();
  vtkDataArray* values = image ? image->GetPointData()->GetArray(chosen.name.c_str()) : nullptr;
  if (!values || values->GetNumberOfComponents() != 3)
    throw Error(concat(file, ": vtkResampleToImage produced no array '", chosen.name, "'"));
  vtkDataArray* mask = image->GetPointData()->GetArray(resample->GetMaskArrayName());
  std::vector<glm::vec3> out;
  reportNonFinite(copyVectors(values, mask, out), path, chosen.name, report);
  report.resampled = true;
  double b[6];
  image->GetBounds(b);
  Box bounds{{float(b[0]), float(b[2]), float(b[4])}, {float(b[1]), float(b[3]), float(b[5])}};
  VectorField field(bounds, dims, std::move(out));
  field.setValidity(validityOf(mask));
  copyScalars(image->GetPointData(), mask, image->GetNumberOfPoints(), path, field, report);
  noteOutside(field, path, report);
  return field;
}

}  // namespace sandstorm
