#include "core/io/vtk_field_extractor.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <type_traits>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkPartitionedDataSet.h>
#include <vtkPointData.h>
#include <vtkRectilinearGrid.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>

#include "core/io/budget_advice.h"
#include "core/io/mesh_resampler.h"
#include "core/io/point_cloud_interpolator.h"
#include "core/io/sampling_grid.h"
#include "core/io/vector_array_choice.h"
#include "core/io/vtk_blocks.h"
#include "core/util/error.h"
#include "core/util/half_arrays.h"
#include "core/util/log.h"
#include "core/util/parallel_for.h"

namespace sandstorm {
namespace {

void listArrays(const std::vector<VtkBlock>& blocks, LoadReport& report) {
  auto list = [&](vtkFieldData* fd, const char* where) {
    for (int i = 0; i < fd->GetNumberOfArrays(); ++i) {
      vtkAbstractArray* a = fd->GetAbstractArray(i);
      const std::string item = concat(a->GetName() ? a->GetName() : "(unnamed)", " (",
                                      a->GetNumberOfComponents(), " components", where, ")");
      if (std::find(report.available.begin(), report.available.end(), item) ==
          report.available.end())
        report.available.push_back(item);
    }
  };
  for (const VtkBlock& b : blocks) {
    list(b.data->GetPointData(), "");
    list(b.data->GetCellData(), ", cell data");
  }
}

// A validity mask as one byte a point (as VTK's readers and
// vtkResampleToImage make it), or nullptr for none or one laid out otherwise.
const std::uint8_t* byteMaskOf(vtkDataArray* mask) {
  const bool bytes = mask && mask->GetNumberOfComponents() == 1 && mask->GetDataTypeSize() == 1 &&
                     mask->HasStandardMemoryLayout();
  return bytes ? static_cast<const std::uint8_t*>(mask->GetVoidPointer(0)) : nullptr;
}

// Copies `n` x y z tuples into `out` over the cores, zeroing non-finite ones
// and those `valid` marks invalid; counts the non-finite ones and gathers the
// range of the valid ones as copied (VectorField::rememberRange). `out` may be
// `in` itself (floats zeroed in place). With `half`, every component is also
// rounded to the nearest half (field.precision = "half") in the same pass, a
// block at a time while it is in the cache, and the range is the rounded
// values'; a component beyond what a half holds stops its chunk and is
// reported (beyond: the first such point), and `out` is then left partly
// rounded, for a caller that drops it.
struct Copied {
  std::size_t nonFinite = 0;
  ValueRange range;
  std::size_t beyond = SIZE_MAX;
  float beyondValue = 0.0f;
};
// Whether each of n floats is finite with |value| at most `limit` (its bits
// with the sign cleared compare as the magnitudes do, NaN and Inf above every
// finite float): a branch-free pass the compiler vectorizes.
bool allWithin(const float* values, std::size_t n, float limit) {
  const std::uint32_t limitBits = std::bit_cast<std::uint32_t>(limit);
  std::uint32_t largest = 0;
  for (std::size_t k = 0; k < n; ++k)
    largest = std::max(largest, std::bit_cast<std::uint32_t>(values[k]) & 0x7fffffffu);
  return largest <= limitBits;
}

template <class T>
Copied copyContiguous(const T* in, const std::uint8_t* valid, glm::vec3* out, std::size_t n,
                      bool half = false) {
  const bool inPlace = static_cast<const void*>(in) == static_cast<const void*>(out);
  constexpr std::size_t kBlock = 2048;  // points: 24 KiB, a rounded block stays in L1/L2
  std::mutex mutex;
  Copied all;
  forChunks(n, [&](std::size_t begin, std::size_t end) {
    Copied part;
    for (std::size_t block = begin; block < end && part.beyond == SIZE_MAX; block += kBlock) {
      const std::size_t blockEnd = std::min(end, block + kBlock);
      // The usual block, floats in place with no mask and nothing to zero
      // or refuse: checked in one vectorized pass, nothing written back but
      // the rounding.
      if constexpr (std::is_same_v<T, float>) {
        const float limit = half ? VectorField::kHalfMax : std::numeric_limits<float>::max();
        if (inPlace && !valid && allWithin(&out[block].x, 3 * (blockEnd - block), limit)) {
          if (half) roundToHalves(&out[block].x, 3 * (blockEnd - block));
          for (std::size_t i = block; i < blockEnd; ++i)
            part.range.add(out[i]);
          continue;
        }
      }
      for (std::size_t i = block; i < blockEnd; ++i) {
        const glm::vec3 v{float(in[3 * i]), float(in[3 * i + 1]), float(in[3 * i + 2])};
        const bool finite = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
        const bool masked = valid && valid[i] == 0;
        part.nonFinite += finite || masked ? 0 : 1;
        const glm::vec3 kept = finite && !masked ? v : glm::vec3(0.0f);
        if (half) {
          for (int c = 0; c < 3; ++c)
            if (std::abs(kept[c]) > VectorField::kHalfMax && part.beyond == SIZE_MAX) {
              part.beyond = i;
              part.beyondValue = kept[c];
            }
          out[i] = kept;
        } else {
          if (!masked) part.range.add(kept);
          // In place, a kept vector is not written back: a series' step is
          // 200 MB, and rewriting it all would double this pass's memory traffic.
          if (!inPlace || !finite || masked) out[i] = kept;
        }
      }
      if (half && part.beyond == SIZE_MAX) {
        roundToHalves(&out[block].x, 3 * (blockEnd - block));
        for (std::size_t i = block; i < blockEnd; ++i)
          if (!valid || valid[i] != 0) part.range.add(out[i]);
      }
    }
    std::lock_guard lock(mutex);
    all.nonFinite += part.nonFinite;
    all.range.merge(part.range);
    if (part.beyond < all.beyond) {
      all.beyond = part.beyond;
      all.beyondValue = part.beyondValue;
    }
  });
  return all;
}

// Copies an array's tuples into `out`, zeroing non-finite ones and those
// `mask` marks invalid. Float and double arrays laid out as x y z x y z (what
// every reader makes of a file's vectors) are copied from their memory over
// the cores; any other array through VTK's generic accessors.
std::size_t copyVectors(vtkDataArray* array, vtkDataArray* mask, std::vector<glm::vec3>& out) {
  const vtkIdType n = array->GetNumberOfTuples();
  out.resize(std::size_t(n));
  const std::uint8_t* valid = byteMaskOf(mask);
  if (array->GetNumberOfComponents() == 3 && (!mask || valid)) {
    if (auto* f = vtkFloatArray::FastDownCast(array))
      return copyContiguous(f->GetPointer(0), valid, out.data(), out.size()).nonFinite;
    if (auto* d = vtkDoubleArray::FastDownCast(array))
      return copyContiguous(d->GetPointer(0), valid, out.data(), out.size()).nonFinite;
  }
  std::size_t nonFinite = 0;
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

// A float array of x y z tuples (what VTK's readers make of a .vti's
// vectors) is kept as the grid's values instead of copied, so that a grid is
// held once: its non-finite tuples and those `mask` marks invalid are zeroed
// in place. nullopt for any other array (then copied: copyVectors).
// With `half`, the values are rounded to halves in the same pass (Error for
// a component beyond what a half holds).
std::optional<VectorValues> adoptVectors(vtkDataArray* array, vtkDataArray* mask, bool half,
                                         std::size_t& nonFinite, ValueRange& range) {
  auto* f = vtkFloatArray::FastDownCast(array);
  const std::uint8_t* valid = byteMaskOf(mask);
  if (!f || f->GetNumberOfComponents() != 3 || (mask && !valid)) return std::nullopt;
  const std::size_t n = std::size_t(f->GetNumberOfTuples());
  auto* values = reinterpret_cast<glm::vec3*>(f->GetPointer(0));
  const Copied copied = copyContiguous(f->GetPointer(0), valid, values, n, half);
  if (copied.beyond != SIZE_MAX) throw VectorField::beyondHalf(copied.beyond, copied.beyondValue);
  nonFinite = copied.nonFinite;
  range = copied.range;
  // The array lives on in the grid; VTK counts its references atomically.
  auto owner = std::make_shared<vtkSmartPointer<vtkFloatArray>>(f);
  return VectorValues::adopt(values, n, std::move(owner));
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

// A note on how a file was read, kept in the report and logged: at info
// level for a read a person waits for, at debug level for a series' steps
// read in the background (each step would say it again). Marked logged, so
// the caller that logs the report's notes does not say it twice.
void noteRead(const LoadOptions& options, const std::string& where, const std::string& note,
              LoadReport& report) {
  report.notes.push_back(note);
  report.notesLogged.push_back(note);
  if (options.showProgress)
    log::info(where, ": ", note);
  else
    log::debug(where, ": ", note);
}

void noteOutside(const VectorField& field, const std::filesystem::path& path,
                 const LoadOptions& options, LoadReport& report) {
  report.outside = field.invalidCount();
  if (report.outside == 0) return;
  const std::string note =
      concat(report.outside, " of ", field.pointCount(),
             " points lie outside the file's cells: marked outside the field (particles there "
             "follow sim.boundary)");
  noteRead(options, path.string(), note, report);
}

// `perPoint`: bytes a point takes (12 for the vector, 4 per scalar array).
void checkBudget(const glm::ivec3& dims, const std::filesystem::path& path,
                 const LoadOptions& options, double perPoint) {
  for (int a = 0; a < 3; ++a)
    if (dims[a] <= 0)
      throw Error(concat(path.string(), ": field.resolution along ", "xyz"[a], " is ", dims[a],
                         "; expected a positive point count"));
  const double points = double(dims.x) * dims.y * dims.z;
  if (points > double(VectorField::kMaxPoints) || points * perPoint > double(options.memoryBudget))
    throw Error(concat(
        path.string(), ": a ", dims.x, "x", dims.y, "x", dims.z, " grid needs ", points * perPoint,
        " bytes, beyond the memory budget (field.memory_budget) of ", options.memoryBudget,
        " bytes; choose a lower resolution (field.resolution, or sandstorm-field --dims)",
        points > double(VectorField::kMaxPoints)
            ? std::string()
            : concat(", or raise field.memory_budget to at least ",
                     budgetValueAtLeast(points * perPoint))));
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

// With options.halfPrecision (field.precision = "half"), a float array is
// rounded to halves as it is checked: the field comes back marked half.
VectorField copyImage(vtkImageData* image, const std::string& name,
                      const std::filesystem::path& path, const LoadOptions& options,
                      LoadReport& report) {
  const std::string file = path.string();
  const bool half = options.halfPrecision;
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
  std::size_t nonFinite = 0;
  std::optional<ValueRange> range{ValueRange{}};
  std::optional<VectorValues> values = adoptVectors(array, mask, half, nonFinite, *range);
  const bool rounded = half && values;
  if (!values) {
    range.reset();
    std::vector<glm::vec3> copied;
    nonFinite = copyVectors(array, mask, copied);
    values = VectorValues(std::move(copied));
  }
  reportNonFinite(nonFinite, path, name, report);
  VectorField field(bounds, dims, std::move(*values));
  field.setValidity(validityOf(mask));
  if (range) field.rememberRange(*range);  // found in the check, over the same valid points
  if (rounded) field.markRoundedToHalf();
  copyScalars(image->GetPointData(), mask, image->GetNumberOfPoints(), path, field, report);
  noteOutside(field, path, options, report);
  return field;
}

}  // namespace

VectorField extractVectorField(vtkDataObject* object, const std::filesystem::path& path,
                               const LoadOptions& options, LoadReport& report) {
  const std::string file = path.string();
  const std::vector<VtkBlock> blocks = vtkBlocks(object);
  if (blocks.empty()) throw Error(concat(file, ": holds no points (no dataset, or empty blocks)"));
  listArrays(blocks, report);
  // A parallel file's pieces (a partitioned dataset) are one dataset in
  // parts, not blocks to list.
  const bool composite = vtkDataSet::SafeDownCast(object) == nullptr &&
                         vtkPartitionedDataSet::SafeDownCast(object) == nullptr;
  for (const VtkBlock& b : blocks) {
    report.cells += std::uint64_t(b.data->GetNumberOfCells());
    report.points += std::uint64_t(b.data->GetNumberOfPoints());
    if (composite) report.blocks.push_back(concat(b.name, ": ", describeBlock(b.data)));
  }
  const VectorChoice choice = chooseVectorArray(blocks, path, options, report);
  report.arrayName = choice.name;

  std::vector<VtkBlock> used;
  std::vector<std::string> without;
  for (const VtkBlock& b : blocks) {
    vtkSmartPointer<vtkDataSet> data = pointVectors(b, choice, path, report);
    if (!data) {
      without.push_back(b.name);
      continue;
    }
    vtkDataArray* array = data->GetPointData()->GetArray(choice.name.c_str());
    if (array && array->GetNumberOfComponents() != 3)
      throw Error(concat(file, composite ? concat(": block '", b.name, "'") : std::string(),
                         ": array '", choice.name, "' has ", array->GetNumberOfComponents(),
                         " components at the points; expected a 3-component vector array"));
    if (!array || array->GetNumberOfTuples() != data->GetNumberOfPoints())
      throw Error(concat(file, composite ? concat(": block '", b.name, "'") : std::string(),
                         ": array '", choice.name, "' holds ",
                         array ? array->GetNumberOfTuples() : 0, " vectors for ",
                         data->GetNumberOfPoints(), " points"));
    used.push_back({b.name, data});
  }
  if (used.empty())
    throw Error(concat(file, ": no block holds '", choice.name,
                       "' whole (its components at the points in some blocks and the cells in "
                       "others?); arrays present: ",
                       arrayInventory(blocks)));
  if (!without.empty()) {
    std::string names;
    for (const std::string& n : without)
      names += concat(names.empty() ? "'" : ", '", n, "'");
    const std::string note = concat(without.size(), " of ", blocks.size(), " blocks carry no '",
                                    choice.name, "' and are left out: ", names);
    noteRead(options, file, note, report);
  }

  const bool single = used.size() == 1;
  // A structured parallel file's pieces: their reader gave the whole grid's.
  if (single) report.sourceDims = nativeDims(used.front().data);
  const bool structured = report.sourceDims != glm::ivec3(0);
  const bool keep = options.resolution == glm::ivec3(0) || options.resolution == report.sourceDims;
  if (auto* image = vtkImageData::SafeDownCast(used.front().data); single && image && keep)
    return copyImage(image, choice.name, path, options, report);

  // The scalar arrays every block carries travel with the vectors.
  std::vector<std::string> scalars;
  vtkPointData* first = used.front().data->GetPointData();
  for (int i = 0; i < first->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = first->GetArray(i);
    if (!a || !a->GetName() || a->GetNumberOfComponents() != 1 ||
        std::string_view(a->GetName()).starts_with("vtk") || a->GetName() == choice.name)
      continue;
    const bool everywhere = std::all_of(used.begin(), used.end(), [&](const VtkBlock& b) {
      vtkDataArray* other = b.data->GetPointData()->GetArray(a->GetName());
      return other && other->GetNumberOfComponents() == 1 &&
             other->GetNumberOfTuples() == b.data->GetNumberOfPoints();
    });
    if (everywhere) scalars.emplace_back(a->GetName());
  }
  const double perPoint = 13.0 + 4.0 * double(scalars.size());
  // A series' step onto its first step's box (options.samplingBox), else its
  // own; its own where the two are the same floats (a mesh that did not move
  // samples at exactly the points its first step did).
  SamplingBounds bounds = boundsOf(used);
  if (const std::optional<Box>& box = options.samplingBox;
      box && options.resolution != glm::ivec3(0) &&
      (glm::vec3(bounds.min) != box->min || glm::vec3(bounds.max) != box->max))
    bounds = SamplingBounds{glm::dvec3(box->min), glm::dvec3(box->max)};
  glm::ivec3 dims = options.resolution;
  if (dims == glm::ivec3(0)) {
    if (structured) {
      dims = report.sourceDims;
    } else {
      std::string note;
      dims = meshResolution(used, bounds, perPoint, options.memoryBudget, note);
      noteRead(options, file, note, report);
    }
  }
  checkBudget(dims, path, options, perPoint);

  UniformGrid grid;
  grid.origin = bounds.min;
  grid.dims = dims;
  for (int a = 0; a < 3; ++a)
    grid.spacing[a] = dims[a] > 1 ? (bounds.max[a] - bounds.min[a]) / (dims[a] - 1) : 0.0;
  std::vector<MeshSource> sources;
  for (const VtkBlock& b : used) {
    MeshSource s;
    s.data = b.data;
    s.arrays.push_back(b.data->GetPointData()->GetArray(choice.name.c_str()));
    for (const std::string& name : scalars)
      s.arrays.push_back(b.data->GetPointData()->GetArray(name.c_str()));
    sources.push_back(std::move(s));
  }
  // Points without cells (a particle tracker's vectors) are interpolated
  // between, within twice their mean spacing; cells are resampled.
  std::size_t clouds = 0;
  for (const VtkBlock& b : used)
    clouds += isPointCloud(b.data) ? 1 : 0;
  if (clouds > 0 && clouds < used.size())
    throw Error(concat(file, ": ", clouds, " of its ", used.size(),
                       " blocks are points without cells and the others meshes; expected one "
                       "or the other"));
  ResampledArrays sampled;
  if (clouds > 0) {
    const double radius = 2.0 * cloudSpacing(used, bounds);
    const std::string note = concat(
        "points without cells: each grid point the inverse-square-distance mean of the "
        "points within ",
        radius,
        " m (twice their mean spacing), outside the field where "
        "there are none");
    noteRead(options, file, note, report);
    sampled = interpolatePointCloud(sources, grid, radius,
                                    concat("interpolating ", path.filename().string()));
  } else {
    sampled = resampleMeshes(sources, grid, concat("resampling ", path.filename().string()));
  }
  report.resampled = true;

  // The resampled vectors become the field's in place (x y z floats, as a
  // VectorValues holds them): the grid is not held twice.
  const std::size_t points = grid.points();
  auto resampled = std::make_shared<std::vector<float>>(std::move(sampled.values[0]));
  auto* vectors = reinterpret_cast<glm::vec3*>(resampled->data());
  std::size_t nonFinite = 0;
  for (std::size_t p = 0; p < points; ++p) {
    glm::vec3& v = vectors[p];
    if (!sampled.valid[p]) {
      v = glm::vec3(0.0f);
    } else if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) {
      v = glm::vec3(0.0f);
      ++nonFinite;
    }
  }
  reportNonFinite(nonFinite, path, choice.name, report);
  Box box{glm::vec3(bounds.min), glm::vec3(bounds.max)};
  VectorField field(box, dims, VectorValues::adopt(vectors, points, resampled));
  field.setValidity(std::move(sampled.valid));
  for (std::size_t s = 0; s < scalars.size(); ++s) {
    std::vector<float>& values = sampled.values[s + 1];
    std::size_t bad = 0;
    for (std::size_t p = 0; p < points; ++p) {
      if (!field.hasValidity() || field.validity()[p]) {
        if (!std::isfinite(values[p])) {
          values[p] = 0.0f;
          ++bad;
        }
      } else {
        values[p] = 0.0f;
      }
    }
    if (bad > 0)
      log::warn(file, ": ", bad, " values of array '", scalars[s],
                "' are NaN, Inf or beyond a float; replaced by zero");
    report.nonFinite += bad;
    field.addScalars(scalars[s], std::move(values));
  }
  noteOutside(field, path, options, report);
  return field;
}

}  // namespace sandstorm
