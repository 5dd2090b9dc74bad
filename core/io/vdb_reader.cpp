#include "core/io/vdb_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <optional>

#include <openvdb/io/File.h>
#include <openvdb/math/Maps.h>
#include <openvdb/tools/Interpolation.h>

#include <nanovdb/NanoVDB.h>
#include <nanovdb/util/OpenToNanoVDB.h>

#include "core/io/budget_advice.h"
#include "core/io/openvdb_grids.h"
#include "core/io/vdb_file_check.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

bool isVec3Type(const std::string& treeType) {
  return treeType.find("vec3s") != std::string::npos || treeType.find("vec3d") != std::string::npos;
}

std::string valueType(const std::string& treeType) {
  // "Tree_vec3s_5_4_3" -> "vec3s"
  if (treeType.rfind("Tree_", 0) != 0) return treeType;
  const std::string rest = treeType.substr(5);
  return rest.substr(0, rest.find('_'));
}

std::string listGrids(const std::vector<VdbGridEntry>& grids) {
  std::string out;
  for (const VdbGridEntry& g : grids) {
    if (!out.empty()) out += ", ";
    out += concat("'", g.name, "' (", valueType(g.type), ")");
  }
  return out;
}

std::string chooseGrid(const std::vector<VdbGridEntry>& grids, const std::string& file,
                       const LoadOptions& options) {
  if (!options.arrayName.empty()) {
    for (const VdbGridEntry& g : grids) {
      if (g.name != options.arrayName) continue;
      if (!isVec3Type(g.type))
        throw Error(concat(
            file, ": grid '", g.name, "' holds ", valueType(g.type),
            " values; expected a Vec3 grid (vec3s or vec3d). Grids present: ", listGrids(grids)));
      return g.name;
    }
    throw Error(concat(file, ": no grid named '", options.arrayName,
                       "'; grids present: ", listGrids(grids)));
  }
  std::vector<std::string> vec3;
  for (const VdbGridEntry& g : grids)
    if (isVec3Type(g.type)) vec3.push_back(g.name);
  if (vec3.size() == 1) return vec3.front();
  throw Error(
      concat(file, ": ", vec3.empty() ? "holds no Vec3 grid" : "holds several Vec3 grids",
             "; choose one by name (--array NAME, or the config's field.name). Grids present: ",
             listGrids(grids)));
}

bool axisAligned(const openvdb::math::Transform& t) {
  const auto map = t.baseMap();
  return map->isType<openvdb::math::ScaleMap>() ||
         map->isType<openvdb::math::ScaleTranslateMap>() ||
         map->isType<openvdb::math::UniformScaleMap>() ||
         map->isType<openvdb::math::UniformScaleTranslateMap>() ||
         map->isType<openvdb::math::TranslationMap>();
}

// `sparseFits`: the grid could be kept sparse instead (axis-aligned, not
// staggered, its own resolution) where the run asked for it dense.
void checkBudget(const glm::ivec3& dims, const std::string& file, const std::string& grid,
                 const openvdb::CoordBBox& bbox, const LoadOptions& options, bool sparseFits) {
  const double points = double(dims.x) * dims.y * dims.z;
  const double bytes = points * 12.0;
  if (points <= double(VectorField::kMaxPoints) && bytes <= double(options.memoryBudget)) return;
  const double limit = std::min(double(options.memoryBudget), 12.0 * VectorField::kMaxPoints);
  const double f = std::cbrt(limit / bytes) * 0.99;
  const glm::ivec3 fit = glm::max(glm::ivec3(glm::floor(glm::vec3(dims) * float(f))), 1);
  throw Error(concat(
      file, ": densifying grid '", grid, "' over its active bounding box (index ", bbox.min(),
      " to ", bbox.max(), ") at ", dims.x, "x", dims.y, "x", dims.z, " points needs ", bytes,
      " bytes, beyond the memory budget (field.memory_budget) of ", options.memoryBudget,
      " bytes. Lower the resolution (field.resolution = [", fit.x, ", ", fit.y, ", ", fit.z,
      "] fits; sandstorm-field --dims ", fit.x, " ", fit.y, " ", fit.z, ")",
      points > double(VectorField::kMaxPoints)
          ? std::string()
          : concat(", or raise field.memory_budget to at least ", budgetValueAtLeast(bytes)),
      sparseFits ? ", or keep it sparse (field.storage = \"sparse\")" : ""));
}

template <class GridT>
VectorField densify(const GridT& grid, const std::string& file, const LoadOptions& options,
                    LoadReport& report) {
  openvdb::CoordBBox bbox = grid.evalActiveVoxelBoundingBox();
  if (bbox.empty()) throw Error(concat(file, ": grid '", grid.getName(), "' has no active voxels"));
  const openvdb::math::Transform& xform = grid.transform();
  const bool aligned = axisAligned(xform);
  const bool staggered = grid.getGridClass() == openvdb::GRID_STAGGERED;
  if (staggered) {
    // A MAC voxel holds its -x, -y and -z faces; its centre needs the next
    // voxel's too. The last layer along +x, +y, +z has no next voxel, so the
    // field covers only the cells whose faces all exist.
    openvdb::Coord top = bbox.max();
    for (int a = 0; a < 3; ++a)
      if (bbox.dim()[a] > 1) top[a] -= 1;
    bbox = openvdb::CoordBBox(bbox.min(), top);
    report.notes.push_back(
        "staggered (MAC) grid: face values averaged to centres; the last layer of voxels along "
        "+x, +y and +z lacks its upper faces, so the field ends at the cells whose faces all "
        "exist");
  }
  const openvdb::Coord extent = bbox.dim();
  report.sourceDims = glm::ivec3(extent.x(), extent.y(), extent.z());

  // World-space box around the active voxels' centres.
  glm::dvec3 lo(1e300), hi(-1e300);
  for (int corner = 0; corner < 8; ++corner) {
    const openvdb::Vec3d ijk(corner & 1 ? bbox.max().x() : bbox.min().x(),
                             corner & 2 ? bbox.max().y() : bbox.min().y(),
                             corner & 4 ? bbox.max().z() : bbox.min().z());
    const openvdb::Vec3d w = xform.indexToWorld(ijk);
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], w[a]);
      hi[a] = std::max(hi[a], w[a]);
    }
  }
  glm::ivec3 dims = options.resolution;
  if (dims == glm::ivec3(0)) {
    if (aligned) {
      dims = report.sourceDims;
    } else {
      // About one point per voxel along each world axis.
      const double voxel = xform.voxelSize().length() / std::sqrt(3.0);
      for (int a = 0; a < 3; ++a)
        dims[a] = int(std::lround((hi[a] - lo[a]) / voxel)) + 1;
    }
  }
  for (int a = 0; a < 3; ++a)
    if (dims[a] <= 0)
      throw Error(concat(file, ": field.resolution along ", "xyz"[a], " is ", dims[a],
                         "; expected a positive point count"));
  checkBudget(dims, file, grid.getName(), bbox, options,
              aligned && !staggered && options.resolution == glm::ivec3(0) &&
                  options.sparse == SparseChoice::Never);
  const bool exact = aligned && !staggered && dims == report.sourceDims;
  report.resampled = !(aligned && dims == report.sourceDims);

  const Box bounds{glm::vec3(lo), glm::vec3(hi)};
  VectorField field(bounds, dims);
  const glm::dvec3 step((hi - lo) / glm::dvec3(glm::max(dims - 1, 1)));
  auto accessor = grid.getConstAccessor();
  using Accessor = decltype(accessor);
  openvdb::tools::GridSampler<Accessor, openvdb::tools::BoxSampler> box(accessor, xform);
  openvdb::tools::GridSampler<Accessor, openvdb::tools::StaggeredBoxSampler> stag(accessor, xform);
  std::size_t nonFinite = 0;
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const glm::dvec3 w = lo + step * glm::dvec3(i, j, k);
        const openvdb::Vec3d world(w.x, w.y, w.z);
        typename GridT::ValueType v;
        if (exact) {
          const openvdb::Vec3d idx = xform.worldToIndex(world);
          v = accessor.getValue(openvdb::Coord(int(std::lround(idx.x())), int(std::lround(idx.y())),
                                               int(std::lround(idx.z()))));
        } else if (staggered) {
          v = stag.wsSample(world);
        } else {
          v = box.wsSample(world);
        }
        glm::vec3 out(float(v.x()), float(v.y()), float(v.z()));
        if (!std::isfinite(out.x) || !std::isfinite(out.y) || !std::isfinite(out.z)) {
          ++nonFinite;
          out = glm::vec3(0.0f);
        }
        field.at(i, j, k) = out;
      }
  report.nonFinite += nonFinite;
  if (nonFinite > 0)
    log::warn(file, ": ", nonFinite, " vectors of grid '", grid.getName(),
              "' are NaN or Inf; replaced by zero");
  return field;
}

bool isScalarType(const std::string& treeType) {
  return treeType == "Tree_float_5_4_3" || treeType == "Tree_double_5_4_3" ||
         treeType == "Tree_float_5_4_3_HalfFloat" || treeType == "Tree_double_5_4_3_HalfFloat";
}

openvdb::GridBase::Ptr readGrid(const std::string& file, const std::string& name) {
  try {
    openvdb::io::File vdb(file);
    vdb.open(false);  // no delayed loading: the file may change after we return
    openvdb::GridBase::Ptr grid = vdb.readGrid(name);
    vdb.close();
    return grid;
  } catch (const std::exception& e) {
    throw Error(concat(file, ": OpenVDB could not read grid '", name, "': ", e.what()));
  }
}

// A float or double grid sampled (trilinearly, in world space) at the field's points.
template <class GridT>
std::vector<float> sampleScalars(const GridT& grid, const VectorField& field,
                                 std::size_t& nonFinite) {
  auto accessor = grid.getConstAccessor();
  openvdb::tools::GridSampler<decltype(accessor), openvdb::tools::BoxSampler> box(accessor,
                                                                                  grid.transform());
  std::vector<float> values(field.pointCount(), 0.0f);
  const glm::ivec3 dims = field.dims();
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const glm::vec3 p = field.pointPosition(i, j, k);
        const float v = float(box.wsSample(openvdb::Vec3d(p.x, p.y, p.z)));
        if (std::isfinite(v))
          values[field.index(i, j, k)] = v;
        else
          ++nonFinite;
      }
  return values;
}

// The file's float and double grids, sampled at the field's points, as its
// scalar arrays (to colour particles by); validated like the vector grid.
// Grids beyond the memory budget are left out, with a note.
void addScalarGrids(const std::filesystem::path& path, const std::vector<VdbGridEntry>& grids,
                    const LoadOptions& options, VectorField& field, LoadReport& report) {
  const std::string file = path.string();
  const double perArray = 4.0 * double(field.pointCount());
  double used = 12.0 * double(field.pointCount());
  for (std::size_t i = 0; i < grids.size(); ++i) {
    if (!isScalarType(grids[i].type) || field.findScalars(grids[i].name)) continue;
    if (used + perArray > double(options.memoryBudget)) {
      report.notes.push_back(
          concat("scalar grid '", grids[i].name,
                 "' left out: it would pass the memory budget (field.memory_budget) of ",
                 options.memoryBudget, " bytes"));
      continue;
    }
    checkVdbGrid(path, grids, i, options.memoryBudget);
    const openvdb::GridBase::Ptr base = readGrid(file, grids[i].name);
    std::size_t nonFinite = 0;
    std::vector<float> values;
    if (auto g = openvdb::gridPtrCast<openvdb::FloatGrid>(base))
      values = sampleScalars(*g, field, nonFinite);
    else if (auto g = openvdb::gridPtrCast<openvdb::DoubleGrid>(base))
      values = sampleScalars(*g, field, nonFinite);
    else
      continue;
    if (nonFinite > 0)
      log::warn(file, ": ", nonFinite, " values of grid '", grids[i].name,
                "' are NaN or Inf; replaced by zero");
    report.nonFinite += nonFinite;
    field.addScalars(grids[i].name, std::move(values));
    used += perArray;
  }
}

// Bytes NanoVDB takes for a Vec3f tree of these node counts (leaf, lower, upper).
double nanoBytes(const std::vector<openvdb::Index32>& nodes, std::size_t rootTiles) {
  using Leaf = nanovdb::NanoLeaf<nanovdb::Vec3f>;
  using Lower = nanovdb::NanoLower<nanovdb::Vec3f>;
  using Upper = nanovdb::NanoUpper<nanovdb::Vec3f>;
  using Root = nanovdb::NanoRoot<nanovdb::Vec3f>;
  return double(sizeof(nanovdb::GridData)) + double(sizeof(nanovdb::TreeData<3>)) +
         double(Root::memUsage(std::uint32_t(rootTiles))) +
         double(nodes[2]) * double(sizeof(typename Upper::DataType)) +
         double(nodes[1]) * double(sizeof(typename Lower::DataType)) +
         double(nodes[0]) * double(sizeof(typename Leaf::DataType));
}

// The grid's active voxel count and the voxels of their box, as the file's
// metadata states them (OpenVDB writes file_voxel_count and file_bbox_min/max
// by default), without reading its tree; nullopt where the file does not say.
std::optional<std::pair<double, double>> statedCounts(const std::string& file,
                                                      const std::string& name) {
  try {
    openvdb::io::File vdb(file);
    vdb.open(false);
    const openvdb::GridBase::Ptr meta = vdb.readGridMetadata(name);
    vdb.close();
    const auto count = meta->getMetadata<openvdb::Int64Metadata>("file_voxel_count");
    const auto lo = meta->getMetadata<openvdb::Vec3IMetadata>("file_bbox_min");
    const auto hi = meta->getMetadata<openvdb::Vec3IMetadata>("file_bbox_max");
    if (!count || !lo || !hi) return std::nullopt;
    double box = 1.0;
    for (int a = 0; a < 3; ++a)
      box *= std::max(0.0, double(hi->value()[a]) - double(lo->value()[a]) + 1.0);
    return std::pair{double(count->value()), box};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// Whether a grid of these counts is better dense: it fills half its box or
// more, and a dense copy fits the budget (a dense grid reads faster).
bool denseEnough(double active, double box, const LoadOptions& options) {
  return active >= 0.5 * box && 12.0 * box <= double(options.memoryBudget);
}

}  // namespace

std::optional<SparseField> readSparseVdb(const std::filesystem::path& path,
                                         const LoadOptions& options, LoadReport& report) {
  if (options.sparse == SparseChoice::Never) return std::nullopt;
  initializeOpenVdb();
  const std::string file = path.string();
  const bool must = options.sparse == SparseChoice::Always;
  const auto cannot = [&](const std::string& why) -> std::optional<SparseField> {
    if (must)
      throw Error(concat(file, ": cannot keep the grid sparse (field.storage = \"sparse\"): ", why,
                         "; field.storage = \"dense\" densifies it"));
    return std::nullopt;
  };
  if (options.resolution != glm::ivec3(0))
    return cannot("field.resolution resamples it onto a dense grid");
  const std::vector<VdbGridEntry> grids = checkVdbFile(path);
  const std::string name = chooseGrid(grids, file, options);
  // "auto" decides from what the file states, where it does, before reading
  // a grid the dense reader would read again.
  if (!must)
    if (const auto stated = statedCounts(file, name);
        stated && denseEnough(stated->first, stated->second, options))
      return std::nullopt;
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (grids[i].name == name) checkVdbGrid(path, grids, i, options.memoryBudget);
  const openvdb::GridBase::Ptr base = readGrid(file, name);
  openvdb::Vec3SGrid::Ptr grid = openvdb::gridPtrCast<openvdb::Vec3SGrid>(base);
  if (!grid) {
    const openvdb::Vec3DGrid::Ptr d = openvdb::gridPtrCast<openvdb::Vec3DGrid>(base);
    if (!d)
      throw Error(concat(file, ": grid '", name, "' is a ", base ? base->type() : "null",
                         " grid; expected a Vec3 grid (vec3s or vec3d)"));
    // NanoVDB's reader on the GPU takes floats: the doubles rounded once.
    const openvdb::Vec3d bg = d->background();
    grid = openvdb::Vec3SGrid::create(openvdb::Vec3s(float(bg.x()), float(bg.y()), float(bg.z())));
    auto out = grid->getAccessor();
    for (auto it = d->tree().cbeginValueOn(); it; ++it) {
      const openvdb::Vec3d v = *it;
      const openvdb::Vec3s f(float(v.x()), float(v.y()), float(v.z()));
      if (it.isVoxelValue())
        out.setValueOn(it.getCoord(), f);
      else
        grid->tree().fill(it.getBoundingBox(), f, true);  // a tile stays a tile
    }
    grid->setTransform(d->transform().copy());
    grid->setGridClass(d->getGridClass());
    grid->setName(d->getName());
  }
  if (!axisAligned(grid->transform())) return cannot("its transform is rotated or not linear");
  if (grid->getGridClass() == openvdb::GRID_STAGGERED)
    return cannot("it is a staggered (MAC) grid, whose faces are averaged to centres densely");
  const openvdb::CoordBBox bbox = grid->evalActiveVoxelBoundingBox();
  if (bbox.empty()) throw Error(concat(file, ": grid '", name, "' has no active voxels"));
  const double active = double(grid->activeVoxelCount());
  const openvdb::Coord extent = bbox.dim();
  const double box = double(extent.x()) * extent.y() * extent.z();
  const double sparseBytes =
      nanoBytes(grid->tree().nodeCount(), grid->tree().root().getTableSize());
  if (sparseBytes > double(options.memoryBudget))
    throw Error(concat(file, ": grid '", name, "' as a sparse grid (", active,
                       " active voxels) takes ", sparseBytes,
                       " bytes, beyond the memory budget (field.memory_budget) of ",
                       options.memoryBudget, " bytes", raiseBudget(sparseBytes)));
  if (!must && denseEnough(active, box, options)) return std::nullopt;
  report.arrayName = name;
  report.sourceDims = glm::ivec3(extent.x(), extent.y(), extent.z());
  for (const VdbGridEntry& g : grids)
    report.available.push_back(concat(g.name, " (", valueType(g.type), " grid)"));
  // NaN and Inf would travel into every sample near them: zero, as densifying does.
  std::size_t nonFinite = 0;
  for (auto it = grid->beginValueOn(); it; ++it) {
    const openvdb::Vec3s v = *it;
    if (!std::isfinite(v.x()) || !std::isfinite(v.y()) || !std::isfinite(v.z())) {
      it.setValue(openvdb::Vec3s(0.0f));
      ++nonFinite;
    }
  }
  report.nonFinite += nonFinite;
  if (nonFinite > 0)
    log::warn(file, ": ", nonFinite, " vectors of grid '", name,
              "' are NaN or Inf; replaced by zero");
  if (options.showProgress)
    log::info(file, ": converting grid '", name, "' (", active, " active voxels) to NanoVDB");
  const nanovdb::GridHandle<nanovdb::HostBuffer> handle = nanovdb::openToNanoVDB(*grid);
  std::vector<std::uint32_t> words((handle.size() + 3) / 4, 0u);
  std::memcpy(words.data(), handle.data(), handle.size());
  report.notes.push_back(concat("kept sparse: ", active, " active voxels in a box of ", extent.x(),
                                "x", extent.y(), "x", extent.z(), " (", 100.0 * active / box,
                                "% filled), ", handle.size(), " bytes (a dense grid: ", 12.0 * box,
                                ")"));
  return SparseField(std::move(words), file);
}

void initializeOpenVdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

VectorField readVdb(const std::filesystem::path& path, const LoadOptions& options,
                    LoadReport& report) {
  initializeOpenVdb();
  const std::string file = path.string();
  const std::vector<VdbGridEntry> grids = checkVdbFile(path);
  for (const VdbGridEntry& g : grids)
    report.available.push_back(concat(g.name, " (", valueType(g.type), " grid)"));
  const std::string name = chooseGrid(grids, file, options);
  report.arrayName = name;
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (grids[i].name == name) checkVdbGrid(path, grids, i, options.memoryBudget);

  const openvdb::GridBase::Ptr base = readGrid(file, name);
  std::optional<VectorField> field;
  if (auto g = openvdb::gridPtrCast<openvdb::Vec3SGrid>(base))
    field = densify(*g, file, options, report);
  else if (auto g = openvdb::gridPtrCast<openvdb::Vec3DGrid>(base))
    field = densify(*g, file, options, report);
  if (field) {
    addScalarGrids(path, grids, options, *field, report);
    return std::move(*field);
  }
  throw Error(concat(file, ": grid '", name, "' is a ", base ? base->type() : "null",
                     " grid; expected a Vec3 grid (vec3s or vec3d)"));
}

}  // namespace sandstorm
